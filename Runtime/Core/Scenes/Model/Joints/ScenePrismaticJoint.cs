using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "prismatic", "axisA", "lower", "upper"}</c>: B slides relative to A along
    /// axis A (in A's frame) without rotating.
    /// </summary>
    public sealed class ScenePrismaticJoint : SceneJoint
    {
        /// <inheritdoc/>
        public override JointKind Type => JointKind.Prismatic;

        /// <summary><c>axisA</c>: the slide axis in A's frame, non-zero. Required.</summary>
        public Vector3 AxisA { get; set; }

        /// <summary><c>lower</c>: lower translation limit, m; null: none.</summary>
        public float? Lower { get; set; }

        /// <summary><c>upper</c>: upper translation limit, m, &gt;= lower; null: none.</summary>
        public float? Upper { get; set; }
    }
}
