using System;
using System.Threading;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// A small pool of persistent worker threads that split an index range into chunks; the
    /// calling thread works too and returns when every chunk is done. Used for one colour of
    /// elements at a time: elements of a colour share no vertex, so the result does not depend
    /// on which thread ran which chunk. Each run is a numbered round published under a lock;
    /// chunks are claimed from a 64-bit counter whose high half is the round, so a worker that
    /// wakes late for a finished round can never claim a chunk of the next one. Idle workers
    /// block on the monitor; nothing is allocated per run. Workers are background threads.
    /// </summary>
    internal sealed class ParallelRanges
    {
        struct Round
        {
            public RangeJob? Job;
            public int Id, Start, End, ChunkSize, ChunkCount;
        }

        readonly object _lock = new object();
        readonly int _threads;
        Round _round;
        long _claims;
        int _done;
        int _posted; // the latest round's id, read without the lock by spinning workers

        // A colour of fewer than two chunks runs on the caller: waking a thread costs more than
        // a few hundred elements (measured: with 32-element chunks a 10k-tet box ran 2-3 times
        // slower on 2 threads than on 1).
        const int MinChunk = 256;

        // Rounds follow each other within microseconds (colour after colour): a worker spins
        // this many short waits for the next one before it blocks on the lock.
        const int SpinRounds = 100;
        bool _stopped; // guarded by _lock

        public ParallelRanges(int threads)
        {
            _threads = Math.Max(1, threads);
            for (int t = 1; t < _threads; t++)
            {
                var worker = new Thread(WorkerLoop) { IsBackground = true, Name = "Fulcrum soft-body worker " + t };
                worker.Start();
            }
        }

        /// <summary>Lets the worker threads end; the pool must not be used afterwards.</summary>
        public void Stop()
        {
            lock (_lock)
            {
                _stopped = true;
                Monitor.PulseAll(_lock);
            }
        }

        /// <summary>Threads taking part, the caller included.</summary>
        public int Threads => _threads;

        /// <summary>Runs <paramref name="job"/> over [start, end) on all threads; returns when done.</summary>
        public void Run(RangeJob job, int start, int end)
        {
            int count = end - start;
            if (count <= 0) return;
            int chunks = Math.Min(_threads * 2, count / MinChunk);
            if (chunks <= 1 || _threads == 1)
            {
                job.Execute(start, end);
                return;
            }
            Round round;
            lock (_lock)
            {
                // Whole blocks of eight: the tet kernels take eight elements at a time and leave a
                // chunk's last few to the scalar kernel.
                int size = ((count + chunks - 1) / chunks + 7) & ~7;
                _round = new Round { Job = job, Id = _round.Id + 1, Start = start, End = end, ChunkSize = size, ChunkCount = (count + size - 1) / size };
                round = _round;
                Volatile.Write(ref _done, 0);
                Volatile.Write(ref _claims, (long)round.Id << 32);
                Volatile.Write(ref _posted, round.Id);
                Monitor.PulseAll(_lock);
            }
            Work(round);
            var spin = new SpinWait();
            while (Volatile.Read(ref _done) < round.ChunkCount) spin.SpinOnce();
            lock (_lock) _round.Job = null;
        }

        void Work(in Round round)
        {
            long first = (long)round.Id << 32;
            while (true)
            {
                long claim = Volatile.Read(ref _claims);
                if (claim < first || claim - first >= round.ChunkCount) return;
                if (Interlocked.CompareExchange(ref _claims, claim + 1, claim) != claim) continue;
                int s = round.Start + (int)(claim - first) * round.ChunkSize;
                round.Job!.Execute(s, Math.Min(round.End, s + round.ChunkSize));
                Interlocked.Increment(ref _done);
            }
        }

        void WorkerLoop()
        {
            int seen = 0;
            while (true)
            {
                Round round;
                for (int spin = 0; spin < SpinRounds && Volatile.Read(ref _posted) == seen; spin++) Thread.SpinWait(20);
                lock (_lock)
                {
                    while (!_stopped && (_round.Id == seen || _round.Job == null)) Monitor.Wait(_lock);
                    if (_stopped) return;
                    round = _round;
                    seen = round.Id;
                }
                Work(round);
            }
        }
    }
}
