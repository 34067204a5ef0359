namespace Fulcrum
{
    public sealed partial class World
    {
        // Written by the stages that know them; read by traces, the runner and tests.
        internal float StatMaxPenetration;
        internal int StatContactCount;
        internal float StatMaxJointError;
        internal int StatReusedManifoldPairs;

        // Cleared at the start of every step; each stage raises what it measures.
        void ResetStatistics()
        {
            StatMaxPenetration = 0;
            StatContactCount = 0;
            StatMaxJointError = 0;
            StatReusedManifoldPairs = 0;
        }

        /// <summary>The deepest penetration among the contacts of the last step, metres (&gt;= 0).</summary>
        public float MaxPenetration => StatMaxPenetration;

        /// <summary>Contact points (in touching manifolds) in the last step.</summary>
        public int ContactCount => StatContactCount;

        /// <summary>The largest position error of any joint after the last step, metres.</summary>
        public float MaxJointError => StatMaxJointError;

        /// <summary>
        /// Shape pairs whose manifolds the last step carried over instead of colliding again
        /// (see <see cref="WorldSettings.ManifoldReuseDistance"/>).
        /// </summary>
        public int ReusedManifoldPairCount => StatReusedManifoldPairs;

        /// <summary>Bodies currently awake (dynamic and kinematic).</summary>
        public int AwakeBodyCount
        {
            get
            {
                int n = 0;
                for (int k = 0; k < Bodies.ActiveCount; k++)
                    if (Bodies.Awake[Bodies.Active[k]]) n++;
                return n;
            }
        }
    }
}
