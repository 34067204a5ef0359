using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Holds attached vertices at their anchors on rigid bodies: a zero-compliance XPBD
    /// distance-to-point constraint shared between the vertex's inverse mass and the body's
    /// generalised inverse mass at the anchor, so the body carries what hangs from it.
    /// A destroyed body releases its vertices.
    /// </summary>
    internal static class AttachmentSolver
    {
        public static void Solve(World world, Attachment[] attachments, Vector3[] x, float[] w, float h, RigidCoupling coupling)
        {
            BodyStorage b = world.Bodies;
            for (int k = 0; k < attachments.Length; k++)
            {
                ref Attachment a = ref attachments[k];
                int slot = a.BodySlot;
                float wv = w[a.Vertex];
                if (wv == 0f || !Anchor(b, a, out Vector3 anchor)) continue;
                Vector3 d = x[a.Vertex] - anchor;
                float length = d.Length();
                if (length < 1e-9f) continue;
                Vector3 n = d / length;
                float dl = length / (wv + coupling.InverseMassAt(slot, anchor, n));
                x[a.Vertex] -= wv * dl * n;
                coupling.Push(slot, anchor, dl * n, h);
            }
        }

        /// <summary>Where attachment <paramref name="a"/>'s body holds its vertex now; false when the body was destroyed.</summary>
        public static bool Anchor(BodyStorage b, in Attachment a, out Vector3 anchor)
        {
            int slot = a.BodySlot;
            if (b.Generation[slot] != a.BodyGeneration || b.ActiveIndex[slot] < 0)
            {
                anchor = default;
                return false;
            }
            anchor = b.Position[slot] + Vector3.Transform(a.LocalAnchor, b.Rotation[slot]);
            return true;
        }

        /// <summary>
        /// After the damping pass: an attached vertex moves with its body, so the velocity the
        /// pass gave it is shared with the body by the impulse J that makes the two move
        /// together, J = (w I + K)^-1 (v - u) (w the vertex's inverse mass, K the body's
        /// <see cref="RigidCoupling.PointInverseMass"/> at the vertex, v the vertex's velocity and
        /// u the body point's): the vertex keeps v - w J, the body gains J, and the pair's
        /// momentum is kept and its energy only lost. Left on the vertex alone, the attachment
        /// dragged the body back to it every substep and a hanging box jittered; handed over
        /// whole (J = m (v - u), right only for a body much heavier than the vertex at that
        /// point), it spun a 33 g body with a cloth pinned 5 m from its centre to NaN within a
        /// step: there the body is lighter than the vertex, and each hand-over overshot.
        /// </summary>
        public static void HandDampingToBodies(World world, Attachment[] attachments, Vector3[] x, Vector3[] v, float[] w, RigidCoupling coupling)
        {
            BodyStorage b = world.Bodies;
            for (int k = 0; k < attachments.Length; k++)
            {
                ref Attachment a = ref attachments[k];
                int slot = a.BodySlot;
                if (b.Generation[slot] != a.BodyGeneration || b.ActiveIndex[slot] < 0 || b.Type[slot] != BodyType.Dynamic) continue;
                int i = a.Vertex;
                if (w[i] == 0f) continue;
                Mat3 k3 = coupling.PointInverseMass(slot, x[i]) + Mat3.Diagonal(new Vector3(w[i]));
                if (!k3.TryInvert(out Mat3 inverse)) continue;
                Vector3 impulse = inverse * (v[i] - coupling.PointVelocity(slot, x[i]));
                coupling.Kick(slot, x[i], impulse);
                v[i] -= w[i] * impulse;
            }
        }

        /// <summary>The largest mass of a live dynamic body with vertices attached, kg (0 for none).</summary>
        public static float HeaviestBody(World world, Attachment[] attachments)
        {
            BodyStorage b = world.Bodies;
            float heaviest = 0;
            for (int k = 0; k < attachments.Length; k++)
            {
                int slot = attachments[k].BodySlot;
                if (b.Generation[slot] == attachments[k].BodyGeneration && b.ActiveIndex[slot] >= 0 && b.Type[slot] == BodyType.Dynamic)
                    heaviest = System.MathF.Max(heaviest, b.Mass[slot]);
            }
            return heaviest;
        }

        /// <summary>Tracks every live body that has vertices attached.</summary>
        public static void Track(World world, Attachment[] attachments, RigidCoupling coupling)
        {
            BodyStorage b = world.Bodies;
            for (int k = 0; k < attachments.Length; k++)
            {
                int slot = attachments[k].BodySlot;
                if (b.Generation[slot] == attachments[k].BodyGeneration && b.ActiveIndex[slot] >= 0) coupling.Track(slot);
            }
        }
    }
}
