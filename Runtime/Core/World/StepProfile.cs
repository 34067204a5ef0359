namespace Fulcrum
{
    /// <summary>Milliseconds spent in each <see cref="StepStage"/> during the last step.</summary>
    public struct StepProfile
    {
        /// <summary>Number of stages (the length of the per-stage buckets).</summary>
        public const int StageCount = 7;

        /// <summary><see cref="StepStage.BroadPhase"/>, ms.</summary>
        public double BroadPhase;
        /// <summary><see cref="StepStage.NarrowPhase"/>, ms.</summary>
        public double NarrowPhase;
        /// <summary><see cref="StepStage.Islands"/>, ms.</summary>
        public double Islands;
        /// <summary><see cref="StepStage.Solve"/>, ms.</summary>
        public double Solve;
        /// <summary><see cref="StepStage.SoftBodies"/>, ms.</summary>
        public double SoftBodies;
        /// <summary><see cref="StepStage.Continuous"/>, ms.</summary>
        public double Continuous;
        /// <summary><see cref="StepStage.SleepAndEvents"/>, ms.</summary>
        public double SleepAndEvents;
        /// <summary>The whole step, ms.</summary>
        public double Total;

        /// <summary>The time of one stage, ms.</summary>
        public readonly double this[StepStage stage] => stage switch
        {
            StepStage.BroadPhase => BroadPhase,
            StepStage.NarrowPhase => NarrowPhase,
            StepStage.Islands => Islands,
            StepStage.Solve => Solve,
            StepStage.SoftBodies => SoftBodies,
            StepStage.Continuous => Continuous,
            _ => SleepAndEvents,
        };

        internal void Add(StepStage stage, double ms)
        {
            switch (stage)
            {
                case StepStage.BroadPhase: BroadPhase += ms; break;
                case StepStage.NarrowPhase: NarrowPhase += ms; break;
                case StepStage.Islands: Islands += ms; break;
                case StepStage.Solve: Solve += ms; break;
                case StepStage.SoftBodies: SoftBodies += ms; break;
                case StepStage.Continuous: Continuous += ms; break;
                default: SleepAndEvents += ms; break;
            }
        }
    }
}
