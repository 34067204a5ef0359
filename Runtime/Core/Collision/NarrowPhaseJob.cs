using System;
using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// The parallel pass of the narrow phase: every contact's manifold reuse or pair function,
    /// run on the worker pool before the serial pass consumes them. Each contact writes only its
    /// own manifolds (reuse, or a rewrite that keeps the chain's length) or its own fixed-size
    /// slot (reduced patches and points), so the result does not depend on which thread ran it;
    /// everything order-dependent (manifold allocation, waking, sorting, statistics) stays in
    /// the serial pass.
    /// Slots are indexed by the contact's dense index at the start of the pass. Allocated once
    /// per world; the slots and the per-block buffers grow before the parallel part, never
    /// inside it.
    /// </summary>
    internal sealed class NarrowPhaseJob : IParallelJob
    {
        /// <summary>Patches kept per pair (the solver takes no more).</summary>
        public const int MaxPatches = ContactGraph.MaxManifoldsPerPair;
        /// <summary>Points kept per pair: four per patch after reduction.</summary>
        public const int MaxPoints = MaxPatches * 4;

        // What the pass found for a slot: nothing (both asleep, a sensor), manifolds reused,
        // a pair function run (its patches kept for the serial pass), fat boxes parted (the
        // serial pass destroys the contact), the shapes out of reach (no pair function), or a
        // pair function run and its manifolds rewritten in place (the chain kept its length).
        const byte None = 0, Reuse = 1, Collide = 2, Parted = 3, OutOfReach = 4, Rewritten = 5;

        readonly NarrowPhase _narrowPhase;
        int[] _contact = new int[64];
        byte[] _result = new byte[64];
        // 1 where the pass finished the contact's update (the serial pass skips it), and its key.
        byte[] _finished = new byte[64];
        ulong[] _key = new ulong[64];
        bool[] _awakeA = new bool[64], _awakeB = new bool[64];
        // A reused contact's touching points and deepest penetration (the step's figures).
        int[] _touching = new int[64];
        float[] _deepest = new float[64];
        float[] _speculative = new float[64];
        int[] _patchCount = new int[64];
        byte[] _patchPoints = new byte[64 * MaxPatches];
        Vector3[] _normal = new Vector3[64 * MaxPatches];
        Vector3[] _position = new Vector3[64 * MaxPoints];
        float[] _separation = new float[64 * MaxPoints];
        uint[] _id = new uint[64 * MaxPoints];
        ContactBuffer[] _buffers = Array.Empty<ContactBuffer>();
        // Per block: last step's points of the contact being rewritten (warm starting).
        ContactPointCache[] _caches = Array.Empty<ContactPointCache>();
        int _blocks;

        /// <summary>Contacts (dense indices) of this step's pass.</summary>
        public int Count;

        /// <summary>A job for <paramref name="narrowPhase"/>'s contacts.</summary>
        public NarrowPhaseJob(NarrowPhase narrowPhase) { _narrowPhase = narrowPhase; }

        /// <summary>The contact of slot <paramref name="i"/>.</summary>
        public int Contact(int i) => _contact[i];

        /// <summary>True when the bodies' awake states are still those slot <paramref name="i"/> was run with.</summary>
        public bool Matches(int i, bool awakeA, bool awakeB) => _result[i] != None && _awakeA[i] == awakeA && _awakeB[i] == awakeB;

        /// <summary>Whether slot <paramref name="i"/>'s contact's fat boxes parted (valid after <see cref="Matches"/>).</summary>
        public bool FoundParted(int i) => _result[i] == Parted;

        /// <summary>Whether slot <paramref name="i"/>'s shapes were out of reach (valid after <see cref="Matches"/>).</summary>
        public bool FoundOutOfReach(int i) => _result[i] == OutOfReach;

        /// <summary>The speculative distance slot <paramref name="i"/> was run with (reused or collided slots).</summary>
        public float Speculative(int i) => _speculative[i];

        /// <summary>Slot <paramref name="i"/>'s contact was found parted (<paramref name="parted"/>) or out of reach.</summary>
        public void SetApart(int i, bool awakeA, bool awakeB, bool parted)
        {
            _result[i] = parted ? Parted : OutOfReach;
            _awakeA[i] = awakeA;
            _awakeB[i] = awakeB;
        }

        /// <summary>Whether slot <paramref name="i"/>'s contact reused its manifolds, with its share of the step's figures.</summary>
        public bool Reused(int i, out int touching, out float deepest)
        {
            touching = _touching[i];
            deepest = _deepest[i];
            return _result[i] == Reuse;
        }

        /// <summary>Whether slot <paramref name="i"/>'s contact had its manifolds rewritten in place.</summary>
        public bool Written(int i) => _result[i] == Rewritten;

        /// <summary>Whether the pass finished slot <paramref name="i"/>'s contact (nothing left for the serial pass but listing it).</summary>
        public bool Finished(int i) => _finished[i] != 0;

        /// <summary>Slot <paramref name="i"/>'s contact, with pair key <paramref name="key"/>, needs nothing more of the serial pass.</summary>
        public void Finish(int i, ulong key)
        {
            _finished[i] = 1;
            _key[i] = key;
        }

        /// <summary>The pair key of finished slot <paramref name="i"/>'s contact.</summary>
        public ulong Key(int i) => _key[i];

        /// <summary>Whether slot <paramref name="i"/>'s contact has manifolds this step (reused or rewritten).</summary>
        public bool Listed(int i) => _result[i] == Reuse || _result[i] == Rewritten;

        /// <summary>Slot <paramref name="i"/> holds contact <paramref name="contact"/>, with no result yet.</summary>
        public void Clear(int i, int contact)
        {
            _contact[i] = contact;
            _result[i] = None;
            _finished[i] = 0;
        }

        /// <summary>Slot <paramref name="i"/>'s contact reused its manifolds in place.</summary>
        public void SetReused(int i, bool awakeA, bool awakeB, float speculative, int touching, float deepest)
        {
            _result[i] = Reuse;
            _speculative[i] = speculative;
            _awakeA[i] = awakeA;
            _awakeB[i] = awakeB;
            _touching[i] = touching;
            _deepest[i] = deepest;
        }

        /// <summary>Slot <paramref name="i"/>'s contact ran its pair function and rewrote its manifolds in place.</summary>
        public void SetWritten(int i, bool awakeA, bool awakeB, float speculative, int touching, float deepest)
        {
            SetReused(i, awakeA, awakeB, speculative, touching, deepest);
            _result[i] = Rewritten;
        }

        /// <summary>Slot <paramref name="i"/>'s contact ran its pair function: keeps the reduced patches.</summary>
        public void SetCollided(int i, bool awakeA, bool awakeB, float speculative, ContactBuffer buffer)
        {
            _result[i] = Collide;
            _speculative[i] = speculative;
            _awakeA[i] = awakeA;
            _awakeB[i] = awakeB;
            Store(i, buffer);
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
            Array.Resize(ref _caches, blocks);
            for (int b = old; b < blocks; b++)
            {
                _buffers[b] = new ContactBuffer();
                _caches[b] = new ContactPointCache();
            }
        }

        void Grow(int n)
        {
            Array.Resize(ref _contact, n);
            Array.Resize(ref _result, n);
            Array.Resize(ref _finished, n);
            Array.Resize(ref _key, n);
            Array.Resize(ref _awakeA, n);
            Array.Resize(ref _awakeB, n);
            Array.Resize(ref _touching, n);
            Array.Resize(ref _deepest, n);
            Array.Resize(ref _speculative, n);
            Array.Resize(ref _patchCount, n);
            Array.Resize(ref _patchPoints, n * MaxPatches);
            Array.Resize(ref _normal, n * MaxPatches);
            Array.Resize(ref _position, n * MaxPoints);
            Array.Resize(ref _separation, n * MaxPoints);
            Array.Resize(ref _id, n * MaxPoints);
        }

        /// <summary>
        /// Runs the pass for the contacts at dense indices [0, <paramref name="count"/>), split
        /// into contiguous blocks over the pool's threads.
        /// </summary>
        public void Run(int count, IParallelScheduler? pool)
        {
            Count = count;
            if (count == 0) return;
            if (_contact.Length < count) Grow(Math.Max(count, 2 * _contact.Length));
            int blocks = BlocksFor(count, pool == null ? 1 : pool.ThreadCount);
            EnsureBuffers(blocks);
            _blocks = blocks;
            if (pool == null) Execute(0, blocks);
            else pool.For(this, 0, blocks, 1);
        }

        /// <summary>Runs the contacts of blocks [<paramref name="start"/>, <paramref name="end"/>).</summary>
        public void Execute(int start, int end)
        {
            for (int b = start; b < end; b++)
            {
                ContactBuffer buffer = _buffers[b];
                ContactPointCache cache = _caches[b];
                int from = (int)((long)Count * b / _blocks), to = (int)((long)Count * (b + 1) / _blocks);
                for (int i = from; i < to; i++) _narrowPhase.Precompute(i, this, buffer, cache);
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
