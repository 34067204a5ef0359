using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    /// <summary>
    /// Enforces <see cref="RigidbodyConstraints"/> around a world step. Core has no per-axis
    /// locks, so the host does it in two halves: before the step the frozen velocity
    /// components are zeroed (the integrator then moves nothing along them), and after the
    /// step whatever the solver put back along them is taken out again: frozen position
    /// components return to their value before the step, and the frozen components of the
    /// step's rotation increment (as a rotation vector in world axes) are removed.
    /// Freezing all three rotation axes is exact instead: the body's inverse inertia is set to
    /// zero (<see cref="Rigidbody"/> does it), so the solver itself cannot turn it.
    /// </summary>
    internal static class AxisFreeze
    {
        public static void BeforeStep(BodyStorage b, int i, RigidbodyConstraints c, out Vector3 position, out Quaternion rotation)
        {
            position = b.Position[i];
            rotation = b.Rotation[i];
            b.LinearVelocity[i] = Mask(b.LinearVelocity[i], c, RigidbodyConstraints.FreezePositionX);
            b.AngularVelocity[i] = Mask(b.AngularVelocity[i], c, RigidbodyConstraints.FreezeRotationX);
        }

        public static void AfterStep(BodyStorage b, int i, RigidbodyConstraints c, Vector3 before, Quaternion rotationBefore)
        {
            Vector3 p = b.Position[i];
            if ((c & RigidbodyConstraints.FreezePositionX) != 0) p.X = before.X;
            if ((c & RigidbodyConstraints.FreezePositionY) != 0) p.Y = before.Y;
            if ((c & RigidbodyConstraints.FreezePositionZ) != 0) p.Z = before.Z;
            Quaternion q = b.Rotation[i];
            if ((c & RigidbodyConstraints.FreezeRotation) == RigidbodyConstraints.FreezeRotation) q = rotationBefore;
            else if ((c & RigidbodyConstraints.FreezeRotation) != 0)
            {
                // The step turned the body by delta = q q0^-1 (world frame); keep only the free axes of it.
                Vector3 turn = Rotation.ToRotationVector(q * Quaternion.Conjugate(rotationBefore));
                turn = Mask(turn, c, RigidbodyConstraints.FreezeRotationX);
                q = Quaternion.Normalize(Rotation.FromRotationVector(turn) * rotationBefore);
            }
            b.Position[i] = p;
            b.Rotation[i] = q;
            b.LinearVelocity[i] = Mask(b.LinearVelocity[i], c, RigidbodyConstraints.FreezePositionX);
            b.AngularVelocity[i] = Mask(b.AngularVelocity[i], c, RigidbodyConstraints.FreezeRotationX);
            b.SyncCenterFromOrigin(i);
            b.UpdateWorldInertia(i);
        }

        // Zeroes the components whose flag is set; xFlag is the x flag of the group (y and z follow it).
        static Vector3 Mask(Vector3 v, RigidbodyConstraints c, RigidbodyConstraints xFlag)
        {
            int bits = (int)c / (int)xFlag;
            if ((bits & 1) != 0) v.X = 0;
            if ((bits & 2) != 0) v.Y = 0;
            if ((bits & 4) != 0) v.Z = 0;
            return v;
        }
    }
}
