using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// A body's motion over one step for continuous collision: the centre of mass moves on a
    /// straight line and the rotation turns on the shortest arc, both uniformly in t in [0, 1].
    /// </summary>
    internal struct BodySweep
    {
        public Vector3 Center0, Center1;
        public Quaternion Rotation0, Rotation1;
        public Vector3 LocalCenter;

        /// <summary>The angle turned over the step, radians.</summary>
        public readonly float Angle
        {
            get
            {
                float d = MathF.Min(1f, MathF.Abs(Quaternion.Dot(Rotation0, Rotation1)));
                return 2f * MathF.Acos(d);
            }
        }

        /// <summary>The body pose (origin and rotation) at fraction <paramref name="t"/>.</summary>
        public readonly Pose BodyPose(float t)
        {
            Quaternion q = t <= 0 ? Rotation0 : t >= 1 ? Rotation1 : Quaternion.Slerp(Rotation0, Rotation1, t);
            Vector3 c = Vector3.Lerp(Center0, Center1, t);
            return new Pose(c - Vector3.Transform(LocalCenter, q), q);
        }

        /// <summary>
        /// The farthest any point within <paramref name="reach"/> of the centre of mass can
        /// move over the step: |dc| + angle * reach (a chord never exceeds its arc).
        /// </summary>
        public readonly float MotionBound(float reach) => Vector3.Distance(Center0, Center1) + Angle * reach;
    }
}
