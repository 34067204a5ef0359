using System;
using System.Numerics;
using Fulcrum.Dynamics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// The pair functions of one step's candidate contacts, run on the worker pool before the
    /// serial narrow-phase pass consumes them. Each candidate writes only its own fixed-size
    /// slot (reduced patches and points), so the result does not depend on which thread ran
    /// it; everything order-dependent (manifold allocation, warm starting, waking, sorting,
    /// statistics) stays in the serial pass. Allocated once per world; the slots and the
    /// per-block buffers grow before the parallel part, never inside it.
    /// </summary>
    internal sealed class NarrowPhaseJob : IParallelJob
    {
        /// <summary>Patches kept per pair (the solver takes no more).</summary>
        public const int MaxPatches = ContactGraph.MaxManifoldsPerPair;
        /// <summary>Points kept per pair: four per patch after reduction.</summary>
        public const int MaxPoints = MaxPatches * 4;

        readonly NarrowPhase _narrowPhase;
        int[] _contact = new int[64];
        bool[] _awakeA = new bool[64], _awakeB = new bool[64];
        int[] _patchCount = new int[64];
        byte[] _patchPoints = new byte[64 * MaxPatches];
        Vector3[] _normal = new Vector3[64 * MaxPatches];
        Vector3[] _position = new Vector3[64 * MaxPoints];
        float[] _separation = new float[64 * MaxPoints];
        uint[] _id = new uint[64 * MaxPoints];
        ContactBuffer[] _buffers = Array.Empty<ContactBuffer>();
        int _blocks;

        /// <summary>Candidates listed for this step.</summary>
        public int Count;

        /// <summary>A job for <paramref name="narrowPhase"/>'s contacts.</summary>
        public NarrowPhaseJob(NarrowPhase narrowPhase) { _narrowPhase = narrowPhase; }

        /// <summary>The contact of candidate <paramref name="i"/>.</summary>
        public int Contact(int i) => _contact[i];

        /// <summary>True when the bodies' awake states are still those the candidate was run with.</summary>
        public bool Matches(int i, bool awakeA, bool awakeB) => _awakeA[i] == awakeA && _awakeB[i] == awakeB;

        /// <summary>Lists a contact whose pair function should run (serial, before <see cref="Run"/>).</summary>
        public void Add(int contact, bool awakeA, bool awakeB)
        {
            if (Count == _contact.Length) Grow(2 * Count);
            _contact[Count] = contact;
            _awakeA[Count] = awakeA;
            _awakeB[Count] = awakeB;
            Count++;
        }

        /// <summary>
        /// Room for <paramref name="candidates"/> candidates and the per-block buffers of a pool
        /// of <paramref name="threads"/> threads (<see cref="World.Reserve"/>), so that a step
        /// growing into that count allocates nothing.
        /// </summary>
        public void Reserve(int candidates, int threads)
        {
            if (_contact.Length < candidates) Grow(candidates);
            EnsureBuffers(BlocksFor(int.MaxValue, threads));
        }

        // A few blocks per thread balance uneven pairs (meshes, hulls) against boxes.
        static int BlocksFor(int count, int threads) => threads <= 1 ? 1 : Math.Min(count, 4 * threads);

        void EnsureBuffers(int blocks)
        {
            if (_buffers.Length >= blocks) return;
            int old = _buffers.Length;
            Array.Resize(ref _buffers, blocks);
            for (int b = old; b < blocks; b++) _buffers[b] = new ContactBuffer();
        }

        void Grow(int n)
        {
            Array.Resize(ref _contact, n);
            Array.Resize(ref _awakeA, n);
            Array.Resize(ref _awakeB, n);
            Array.Resize(ref _patchCount, n);
            Array.Resize(ref _patchPoints, n * MaxPatches);
            Array.Resize(ref _normal, n * MaxPatches);
            Array.Resize(ref _position, n * MaxPoints);
            Array.Resize(ref _separation, n * MaxPoints);
            Array.Resize(ref _id, n * MaxPoints);
        }

        /// <summary>Runs every listed candidate, split into contiguous blocks over the pool's threads.</summary>
        public void Run(IParallelScheduler? pool)
        {
            if (Count == 0) return;
            int blocks = BlocksFor(Count, pool == null ? 1 : pool.ThreadCount);
            EnsureBuffers(blocks);
            _blocks = blocks;
            if (pool == null) Execute(0, blocks);
            else pool.For(this, 0, blocks, 1);
        }

        /// <summary>Runs the candidates of blocks [<paramref name="start"/>, <paramref name="end"/>).</summary>
        public void Execute(int start, int end)
        {
            for (int b = start; b < end; b++)
            {
                ContactBuffer buffer = _buffers[b];
                int from = (int)((long)Count * b / _blocks), to = (int)((long)Count * (b + 1) / _blocks);
                for (int i = from; i < to; i++)
                {
                    _narrowPhase.CollideContact(_contact[i], buffer);
                    buffer.Reduce();
                    Store(i, buffer);
                }
            }
        }

        void Store(int i, ContactBuffer buffer)
        {
            int patches = Math.Min(buffer.PatchCount, MaxPatches);
            _patchCount[i] = patches;
            int w = i * MaxPoints;
            for (int p = 0; p < patches; p++)
            {
                int start = buffer.PatchStart[p], count = buffer.PatchPointCount(p);
                _normal[i * MaxPatches + p] = buffer.PatchNormal[p];
                _patchPoints[i * MaxPatches + p] = (byte)count;
                for (int k = 0; k < count; k++, w++)
                {
                    _position[w] = buffer.Position[start + k];
                    _separation[w] = buffer.Separation[start + k];
                    _id[w] = buffer.Id[start + k];
                }
            }
        }

        /// <summary>Writes candidate <paramref name="i"/>'s reduced patches into <paramref name="buffer"/>.</summary>
        public void Restore(int i, ContactBuffer buffer, float speculative)
        {
            buffer.Clear(speculative);
            int r = i * MaxPoints;
            for (int p = 0; p < _patchCount[i]; p++)
            {
                buffer.BeginPatch(_normal[i * MaxPatches + p]);
                int count = _patchPoints[i * MaxPatches + p];
                for (int k = 0; k < count; k++, r++)
                    buffer.Add(_position[r], _separation[r], _id[r]);
            }
        }
    }
}
