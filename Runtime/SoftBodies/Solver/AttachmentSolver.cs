using System.Numerics;

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
                if (b.Generation[slot] != a.BodyGeneration || b.ActiveIndex[slot] < 0) continue;
                float wv = w[a.Vertex];
                if (wv == 0f) continue;
                Vector3 anchor = b.Position[slot] + Vector3.Transform(a.LocalAnchor, b.Rotation[slot]);
                Vector3 d = x[a.Vertex] - anchor;
                float length = d.Length();
                if (length < 1e-9f) continue;
                Vector3 n = d / length;
                float dl = length / (wv + coupling.InverseMassAt(slot, anchor, n));
                x[a.Vertex] -= wv * dl * n;
                coupling.Push(slot, anchor, dl * n, h);
            }
        }

        /// <summary>
        /// After the damping pass: an attached vertex moves with its body, so the velocity the
        /// pass took from it (m dv, against <paramref name="before"/>) is handed to the body,
        /// and the vertex takes the body's point velocity again. Left on the vertex alone, the
        /// attachment dragged the body back to it every substep and a hanging box jittered.
        /// </summary>
        public static void HandDampingToBodies(World world, Attachment[] attachments, Vector3[] x, Vector3[] v, float[] m,
            Vector3[] before, RigidCoupling coupling)
        {
            BodyStorage b = world.Bodies;
            for (int k = 0; k < attachments.Length; k++)
            {
                ref Attachment a = ref attachments[k];
                int slot = a.BodySlot;
                if (b.Generation[slot] != a.BodyGeneration || b.ActiveIndex[slot] < 0 || b.Type[slot] != BodyType.Dynamic) continue;
                int i = a.Vertex;
                coupling.Kick(slot, x[i], m[i] * (v[i] - before[k]));
                v[i] = coupling.PointVelocity(slot, x[i]);
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
