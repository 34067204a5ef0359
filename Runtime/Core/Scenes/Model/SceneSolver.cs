namespace Fulcrum.Scenes
{
    /// <summary>The <c>solver</c> object of a scene; defaults follow <see cref="WorldSettings.Default"/>.</summary>
    public sealed class SceneSolver
    {
        /// <summary><c>type</c>: <c>"pgs"</c> or <c>"tgs"</c>. Default: tgs.</summary>
        public SolverType Type { get; set; } = SolverType.Tgs;

        /// <summary><c>iterations</c>: velocity iterations (per step for PGS, per substep for TGS), &gt;= 1. Default: 4.</summary>
        public int Iterations { get; set; } = 4;

        /// <summary><c>substeps</c>: TGS substeps per step (PGS ignores it), &gt;= 1. Default: 4.</summary>
        public int Substeps { get; set; } = 4;

        /// <summary>
        /// <c>contactHertz</c>: stiffness of the soft contact constraint, Hz, &gt; 0 (an extension
        /// of fulcrum-scene/1). Null: <see cref="WorldSettings.ContactHertz"/>'s default.
        /// </summary>
        public float? ContactHertz { get; set; }

        /// <summary>
        /// <c>jointHertz</c>: stiffness of the joints' position correction, Hz, &gt; 0 (an
        /// extension; heavy loads on light chains want more). Null: the WorldSettings default.
        /// </summary>
        public float? JointHertz { get; set; }
        /// <summary>
        /// <c>manifoldReuse</c>: the relative motion, m, below which a touching pair keeps its
        /// manifold instead of colliding again (<see cref="WorldSettings.ManifoldReuseDistance"/>;
        /// an extension), &gt;= 0; 0 turns reuse off. Null: the WorldSettings default (1 mm).
        /// </summary>
        public float? ManifoldReuse { get; set; }

        /// <summary>
        /// <c>shockPropagation</c>: the sweep (TGS and PGS) that stops heavy loads sinking into light bodies
        /// (<see cref="WorldSettings.ShockPropagation"/>; an extension). Null: the default (on).
        /// </summary>
        public bool? ShockPropagation { get; set; }

        /// <summary>
        /// <c>jointTrees</c>: the block solve (TGS; PGS's velocity passes) of the anchor rows of joints that form trees, so a
        /// heavy load on light links holds (<see cref="WorldSettings.JointTrees"/>; an extension).
        /// Null: the default (on).
        /// </summary>
        public bool? JointTrees { get; set; }

        /// <summary>
        /// <c>shockDepth</c>: the depth, m, past which the sweep stops a contact sinking
        /// (<see cref="WorldSettings.ShockDepth"/>; an extension), &gt;= 0. Null: the default (2 mm).
        /// </summary>
        public float? ShockDepth { get; set; }

        /// <summary>
        /// <c>maxJointCorrectionSpeed</c>: the fastest a violated joint is pulled back, m/s or rad/s
        /// (<see cref="WorldSettings.MaxJointCorrectionSpeed"/>; an extension), &gt; 0. Null: the default (4).
        /// </summary>
        public float? MaxJointCorrectionSpeed { get; set; }
    }
}
