using System.Numerics;
using System.Runtime.CompilerServices;

namespace Fulcrum.Collision
{
    /// <summary>
    /// One contact point of a manifold. Written by the narrow phase (geometry, feature id)
    /// and by the solver (accumulated impulses, which the narrow phase carries to the next
    /// step for warm starting when the feature id matches).
    /// </summary>
    public struct ContactPoint
    {
        /// <summary>World position, midway between the two surfaces, metres.</summary>
        public Vector3 Position;
        /// <summary>Anchor on body A relative to A's centre of mass, world axes, metres.</summary>
        public Vector3 AnchorA;
        /// <summary>Anchor on body B relative to B's centre of mass, world axes, metres.</summary>
        public Vector3 AnchorB;
        /// <summary>Signed distance along the normal: negative = penetration, positive = speculative gap, metres.</summary>
        public float Separation;
        /// <summary>Identifies the pair of features (vertex/edge/face) that made the point; equal ids persist.</summary>
        public uint FeatureId;
        /// <summary>
        /// Accumulated normal impulse, N s (&gt;= 0): the solver's estimate of the impulse per
        /// step, kept for the next step's warm start. With TGS substeps it is the last substep's
        /// impulse times the substep count, not what was applied: read
        /// <see cref="AppliedImpulse"/> for that.
        /// </summary>
        public float NormalImpulse;
        /// <summary>
        /// The normal impulse the solver actually applied at this point over the whole step
        /// (every substep plus restitution), N s: what events and force readouts report.
        /// </summary>
        public float AppliedImpulse;
        /// <summary>Accumulated friction impulse along the manifold's first tangent, N s.</summary>
        public float TangentImpulse1;
        /// <summary>Accumulated friction impulse along the manifold's second tangent, N s.</summary>
        public float TangentImpulse2;
        /// <summary>Relative normal velocity before the solve (for restitution), m/s.</summary>
        public float RelativeNormalVelocity;
        /// <summary>True when the point existed last step (its impulses were carried over).</summary>
        public bool Persisted;
    }

    /// <summary>
    /// Up to four contact points between two shapes sharing one normal. Manifolds of all
    /// touching pairs live in the world's contact set for the solver to read and write.
    /// </summary>
    public struct ContactManifold
    {
        /// <summary>The most points a manifold keeps.</summary>
        public const int MaxPoints = 4;

        /// <summary>Body slot of shape A.</summary>
        public int BodyA;
        /// <summary>Body slot of shape B.</summary>
        public int BodyB;
        /// <summary>Shape slot A.</summary>
        public int ShapeA;
        /// <summary>Shape slot B.</summary>
        public int ShapeB;
        /// <summary>World normal, unit, pointing from A to B.</summary>
        public Vector3 Normal;
        /// <summary>Points in use (0..4).</summary>
        public int PointCount;
        /// <summary>Point 0.</summary>
        public ContactPoint Point0;
        /// <summary>Point 1.</summary>
        public ContactPoint Point1;
        /// <summary>Point 2.</summary>
        public ContactPoint Point2;
        /// <summary>Point 3.</summary>
        public ContactPoint Point3;
        /// <summary>Combined friction coefficient.</summary>
        public float Friction;
        /// <summary>Combined restitution coefficient.</summary>
        public float Restitution;
        /// <summary>Rolling resistance (torque per unit normal force, metres); 0 disables it.</summary>
        public float RollingFriction;
        /// <summary>Accumulated rolling-friction angular impulse (warm start).</summary>
        public Vector3 RollingImpulse;

        /// <summary>Point <paramref name="i"/> (0..3) of <paramref name="m"/> by reference.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static ref ContactPoint Point(ref ContactManifold m, int i)
        {
#if NET
            // The four points are consecutive fields of one type (sequential layout).
            return ref Unsafe.Add(ref m.Point0, (uint)i > 3u ? 3 : i);
#else
            switch (i)
            {
                case 0: return ref m.Point0;
                case 1: return ref m.Point1;
                case 2: return ref m.Point2;
                default: return ref m.Point3;
            }
#endif
        }
    }
}
