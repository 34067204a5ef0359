using System.Diagnostics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Decides, pass by pass, whether a colour loop runs on the worker pool or on the calling
    /// thread alone, by the time per element each way has taken lately. A pass over the colours
    /// waits for every thread at each colour, so when the machine's cores are busy with other
    /// work a worker that is descheduled holds up the whole colour and two threads ran 2-3
    /// times slower than one (10k and 50k tets on a loaded 2-core machine); when the cores are
    /// free, large colours gain. The results are the same either way (a colour's elements
    /// share no vertex), so the choice changes only the time. Every <see cref="ExploreEvery"/>-th
    /// pass takes the other way, to notice when the load changes.
    /// </summary>
    internal sealed class ThreadChoice
    {
        /// <summary>One pass in this many takes the way not currently preferred.</summary>
        public const int ExploreEvery = 64;

        /// <summary>
        /// The pool is preferred only when its time per element is below this fraction of the
        /// calling thread's: a pass on the pool costs the machine a second core, and within the
        /// timing noise of a busy machine the calling thread alone is the safe side.
        /// </summary>
        public const double Margin = 0.9;

        // Smoothed ticks per element each way; negative until measured.
        double _serial = -1, _parallel = -1;
        int _pass;
        long _start;
        bool _current, _exploring;

        /// <summary>Whether this pass should use the pool; call <see cref="End"/> after it.</summary>
        public bool Begin()
        {
            _pass++;
            if (_parallel < 0) _current = true;
            else if (_serial < 0) _current = false;
            else
            {
                bool prefer = _parallel < Margin * _serial;
                _exploring = _pass % ExploreEvery == 0;
                _current = _exploring ? !prefer : prefer;
            }
            _start = Stopwatch.GetTimestamp();
            return _current;
        }

        /// <summary>Records the time of the pass begun by <see cref="Begin"/> over <paramref name="elements"/> elements.</summary>
        public void End(int elements)
        {
            if (elements <= 0) return;
            Record((double)(Stopwatch.GetTimestamp() - _start) / elements);
        }

        /// <summary>Records a time per element (any unit) for the way the last <see cref="Begin"/> chose.</summary>
        internal void Record(double perElement)
        {
            // The way taken: an exponential average over about four passes, steady against one
            // slow pass. An exploring pass replaces its way's figure, which is 64 passes old.
            ref double figure = ref _current ? ref _parallel : ref _serial;
            figure = figure < 0 || _exploring ? perElement : figure + 0.25 * (perElement - figure);
            _exploring = false;
        }
    }
}
