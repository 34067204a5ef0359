using Fulcrum.Dynamics;

namespace Fulcrum
{
    public sealed partial class World
    {
        // The world's own pool (Settings.Threads - 1 workers), started by the first step that
        // needs it; unused while a host's scheduler is set.
        WorkerPool? _workers;
        IParallelScheduler? _scheduler;

        internal WorkerPool? SolverPoolForTests => _workers;

        /// <summary>
        /// The parallel-for that the step's stages use when <see cref="WorldSettings.Threads"/>
        /// &gt; 1 (solver, narrow phase, soft bodies): null (the default) uses the world's own
        /// pool of <see cref="WorldSettings.Threads"/> - 1 background threads; a host with
        /// threads of its own (Unity's job system, a game's task pool) sets its
        /// <see cref="IParallelScheduler"/> here. Results are bit-identical whichever runs the
        /// work. With <see cref="WorldSettings.Threads"/> = 1 everything runs on the caller and
        /// no scheduler is asked. Not during a step; not saved by <see cref="SaveState"/>.
        /// </summary>
        public IParallelScheduler? Scheduler
        {
            get => _scheduler;
            set
            {
                ThrowIfInStep();
                _scheduler = value;
            }
        }

        // The scheduler of this step's parallel work, or null for none (Threads = 1). The own
        // pool follows Settings.Threads; a change of count replaces it (outside the steady
        // state, so the allocation does not recur).
        internal IParallelScheduler? ParallelScheduler()
        {
            int threads = _settings.Threads;
            if (threads <= 1) return null;
            if (_scheduler != null) return _scheduler;
            if (_workers == null || _workers.ThreadCount != threads)
            {
                _workers?.Stop();
                _workers = new WorkerPool(threads - 1);
            }
            return _workers;
        }

        /// <summary>
        /// Ends the worker threads the world started for <see cref="WorldSettings.Threads"/> &gt; 1
        /// (the one pool that the solver, the narrow phase and the soft bodies share; a host's
        /// <see cref="Scheduler"/> is the host's to stop). A later step with several threads
        /// starts new ones. Call it when a host is done with the world (Unity's play mode ending,
        /// with domain reload off, would otherwise keep the idle threads until the editor quits).
        /// Not during a step.
        /// </summary>
        public void StopThreads()
        {
            ThrowIfInStep();
            _workers?.Stop();
            _workers = null;
        }
    }
}
