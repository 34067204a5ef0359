namespace Fulcrum.Benchmarks.Peers
{
    /// <summary>
    /// A stretch of a scene's steps timed and reported as one row: <see cref="Steps"/> steps
    /// starting <see cref="Start"/> steps after the scene's warm-up.
    /// </summary>
    public readonly struct PeerPhase
    {
        /// <summary>Row name, e.g. "pile 2016 collapse".</summary>
        public readonly string Name;
        /// <summary>First timed step, counted from the end of warm-up.</summary>
        public readonly int Start;
        /// <summary>Timed steps.</summary>
        public readonly int Steps;

        public PeerPhase(string name, int start, int steps)
        {
            Name = name;
            Start = start;
            Steps = steps;
        }

        /// <summary>Whether step <paramref name="step"/> (counted from the end of warm-up) is in this phase.</summary>
        public bool Contains(int step) => step >= Start && step < Start + Steps;
    }
}
