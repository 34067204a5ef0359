using System;
using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// What a pair function writes: one or more patches (a normal from shape A to shape B
    /// and its candidate points: world position midway between the surfaces, separation along
    /// the normal, feature id). Points farther apart than <see cref="Speculative"/> are dropped
    /// on entry. A convex pair makes one patch; a shape against a mesh may make several.
    /// <see cref="Reduce"/> then keeps at most four points per patch. Reused every call: one
    /// per world, no allocation once grown.
    /// </summary>
    internal sealed class ContactBuffer
    {
        public Vector3[] Position = new Vector3[64];
        public float[] Separation = new float[64];
        public uint[] Id = new uint[64];
        public int PointCount;

        public Vector3[] PatchNormal = new Vector3[8];
        public int[] PatchStart = new int[9];
        public int PatchCount;
        ContactBuffer? _scratch;

        /// <summary>A buffer with its scratch buffer made at once: a mesh pair met late in a run
        /// (a pile whose other pairs went to sleep) must not allocate inside a step.</summary>
        public ContactBuffer() : this(true) { }

        ContactBuffer(bool withScratch)
        {
            if (withScratch) _scratch = new ContactBuffer(false);
        }

        /// <summary>Face clipping scratch for box pairs (reused: per-call stack buffers cost their zeroing).</summary>
        public readonly ClipScratch Clip = new ClipScratch();

        /// <summary>The largest separation a point may have and still be kept, metres.</summary>
        public float Speculative;

        /// <summary>A second buffer for pair functions that gather per-part results first (meshes).</summary>
        public ContactBuffer Scratch => _scratch ??= new ContactBuffer(false);

        /// <summary>Empties the buffer for a new pair.</summary>
        public void Clear(float speculative)
        {
            PointCount = 0;
            PatchCount = 0;
            PatchStart[0] = 0;
            Speculative = speculative;
        }

        /// <summary>Starts a patch with a unit normal from A to B; later points belong to it.</summary>
        public void BeginPatch(Vector3 normal)
        {
            // An empty previous patch is replaced rather than kept.
            if (PatchCount > 0 && PatchStart[PatchCount - 1] == PointCount) PatchCount--;
            if (PatchCount == PatchNormal.Length)
            {
                Array.Resize(ref PatchNormal, 2 * PatchNormal.Length);
                Array.Resize(ref PatchStart, 2 * PatchNormal.Length + 1);
            }
            PatchNormal[PatchCount] = normal;
            PatchStart[PatchCount] = PointCount;
            PatchCount++;
            PatchStart[PatchCount] = PointCount;
        }

        /// <summary>Adds a point to the current patch when its separation is within <see cref="Speculative"/>.</summary>
        public void Add(Vector3 position, float separation, uint id)
        {
            if (!(separation <= Speculative)) return;
            if (PointCount == Position.Length)
            {
                Array.Resize(ref Position, 2 * Position.Length);
                Array.Resize(ref Separation, 2 * Separation.Length);
                Array.Resize(ref Id, 2 * Id.Length);
            }
            Position[PointCount] = position;
            Separation[PointCount] = separation;
            Id[PointCount] = id;
            PointCount++;
            PatchStart[PatchCount] = PointCount;
        }

        /// <summary>Drops every point and patch added after the counts given.</summary>
        public void Truncate(int pointCount, int patchCount)
        {
            PointCount = pointCount;
            PatchCount = patchCount;
            PatchStart[patchCount] = pointCount;
        }

        /// <summary>Points in patch <paramref name="p"/>.</summary>
        public int PatchPointCount(int p) => PatchStart[p + 1] - PatchStart[p];

        /// <summary>Turns every normal around (after a pair function ran with A and B swapped).</summary>
        public void FlipNormals()
        {
            for (int p = 0; p < PatchCount; p++) PatchNormal[p] = -PatchNormal[p];
        }

        /// <summary>The smallest separation in the buffer (+infinity when empty).</summary>
        public float MinSeparation()
        {
            float s = float.PositiveInfinity;
            for (int i = 0; i < PointCount; i++) s = MathF.Min(s, Separation[i]);
            return s;
        }

        /// <summary>Drops empty patches and reduces every patch to at most four points spanning its area.</summary>
        public void Reduce()
        {
            int write = 0, writePatch = 0;
            for (int p = 0; p < PatchCount; p++)
            {
                int start = PatchStart[p], count = PatchStart[p + 1] - start;
                if (count == 0) continue;
                if (count > 2)
                    count = ManifoldReduction.Reduce(Position, Separation, Id, start, count, PatchNormal[p]);
                for (int i = 0; i < count; i++)
                {
                    Position[write + i] = Position[start + i];
                    Separation[write + i] = Separation[start + i];
                    Id[write + i] = Id[start + i];
                }
                PatchNormal[writePatch] = PatchNormal[p];
                PatchStart[writePatch] = write;
                write += count;
                writePatch++;
            }
            PatchCount = writePatch;
            PointCount = write;
            PatchStart[writePatch] = write;
        }
    }
}
