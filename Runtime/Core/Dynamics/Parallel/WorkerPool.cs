using System;
using System.Runtime.InteropServices;
using System.Threading;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// The world's own <see cref="IParallelScheduler"/>, for the solver, the narrow phase and
    /// the soft bodies alike: a fixed set of background threads that run one
    /// <see cref="IParallelJob"/> at a time with the caller, splitting its range into chunks
    /// taken in order from a shared counter.
    /// <see cref="For"/> returns when every chunk is done, so a sequence of calls acts as a
    /// sequence of barriers (one per colour batch). Nothing is allocated per call: the job is
    /// an object the caller keeps, and the workers spin briefly, then sleep on an event.
    /// The result never depends on which thread ran which chunk as long as the chunks of one
    /// call write disjoint data, which colouring guarantees for the solver.
    /// </summary>
    internal sealed class WorkerPool : IParallelScheduler
    {
        readonly Thread[] _threads;
        readonly ManualResetEventSlim _wake = new ManualResetEventSlim(false);
        IParallelJob? _job;
        int _start, _end, _chunk, _chunkCount;
        Counters _hot;
        volatile bool _stopped;

        /// <summary>
        /// The counters every thread writes or polls during a call, each on a cache line of its
        /// own (64 bytes, with a line of padding before the first): the chunk claims would
        /// otherwise take the line the idle workers poll and the job's fields away from them at
        /// every claim.
        /// </summary>
        [StructLayout(LayoutKind.Explicit, Size = 256)]
        struct Counters
        {
            /// <summary>Generation (high 32 bits) and next chunk (low 32): a thread still busy with an older call sees the generation change and can never take a chunk of the new one.</summary>
            [FieldOffset(64)] public long Ticket;
            /// <summary>Chunks of the call not yet done; each thread subtracts the ones it ran when it runs out.</summary>
            [FieldOffset(128)] public int Remaining;
            /// <summary>Calls so far: the workers poll it for a new one.</summary>
            [FieldOffset(192)] public int Generation;
        }

        /// <summary>Starts <paramref name="workers"/> background threads (the caller is one more).</summary>
        public WorkerPool(int workers)
        {
            _threads = new Thread[workers];
            for (int i = 0; i < workers; i++)
            {
                _threads[i] = new Thread(WorkerLoop) { IsBackground = true, Name = "Fulcrum worker " + (i + 1) };
                _threads[i].Start();
            }
        }

        /// <summary>Lets the worker threads end (after any call in progress).</summary>
        public void Stop()
        {
            _stopped = true;
            _wake.Set();
        }

        /// <summary>Calls that were split between threads (for tests and profiling).</summary>
        public long SplitCalls;

        /// <summary>Threads that take part in a call, the caller included.</summary>
        public int ThreadCount => _threads.Length + 1;

        /// <summary>
        /// Runs <paramref name="job"/> over [<paramref name="start"/>, <paramref name="end"/>) in
        /// chunks of at least <paramref name="minChunk"/> items; small ranges run on the caller.
        /// </summary>
        public void For(IParallelJob job, int start, int end, int minChunk)
        {
            int count = end - start;
            if (count <= 0) return;
            int chunk = Math.Max(minChunk, (count + 4 * ThreadCount - 1) / (4 * ThreadCount));
            int chunks = (count + chunk - 1) / chunk;
            if (chunks <= 1 || _threads.Length == 0)
            {
                job.Execute(start, end);
                return;
            }
            SplitCalls++;
            // Close the previous call's ticket first ("every chunk taken"). A worker still looping
            // in RunChunks for that call may have read its ticket just before; without this it
            // could compare that stale chunk number against the fields written below for the new
            // call, win the compare-exchange and run a chunk of the new job that the new call
            // then hands out again (twice-solved rows, and _remaining reaching 0 early).
            int previous = Volatile.Read(ref _hot.Generation);
            Interlocked.Exchange(ref _hot.Ticket, ((long)previous << 32) | int.MaxValue);
            _job = job;
            _start = start;
            _end = end;
            _chunk = chunk;
            _chunkCount = chunks;
            Volatile.Write(ref _hot.Remaining, chunks);
            int generation = Interlocked.Increment(ref _hot.Generation);
            Interlocked.Exchange(ref _hot.Ticket, (long)generation << 32);
            _wake.Set();
            RunChunks(generation);
            int spins = 0;
            while (Volatile.Read(ref _hot.Remaining) > 0) Pause(ref spins);
            _wake.Reset();
            _job = null;
        }

        void RunChunks(int generation)
        {
            int done = 0;
            while (true)
            {
                long ticket = Volatile.Read(ref _hot.Ticket);
                if ((int)(ticket >> 32) != generation) break;
                int c = (int)(ticket & 0xFFFFFFFF);
                if (c >= _chunkCount) break;
                if (Interlocked.CompareExchange(ref _hot.Ticket, ticket + 1, ticket) != ticket) continue;
                IParallelJob job = _job!;
                int s = _start + c * _chunk;
                job.Execute(s, Math.Min(_end, s + _chunk));
                done++;
            }
            // One write to the shared count per thread and call, not one per chunk.
            if (done > 0) Interlocked.Add(ref _hot.Remaining, -done);
        }

        // Busy-waits for a short while (a colour batch is microseconds), then yields the core.
        static void Pause(ref int spins)
        {
            if (++spins < 100) Thread.SpinWait(20);
            else Thread.Yield();
        }

        void WorkerLoop()
        {
            int seen = 0;
            while (true)
            {
                int spins = 0;
                while (Volatile.Read(ref _hot.Generation) == seen)
                {
                    if (_stopped) return;
                    if (spins > 2000) _wake.Wait();
                    Pause(ref spins);
                }
                seen = Volatile.Read(ref _hot.Generation);
                RunChunks(seen);
            }
        }
    }
}
