using System;
using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// The persistent contacts: a pool of <see cref="Contact"/> records found by shape pair
    /// through a <see cref="PairMap"/>, listed densely for the narrow phase, and linked per
    /// shape (each contact is an edge with one end in each shape's list) so that removing a
    /// shape finds its contacts without a scan. Manifolds live in a pool of their own, chained
    /// per contact, and keep their accumulated impulses from one step to the next.
    /// Grows amortised; steady-state use allocates nothing.
    /// </summary>
    internal sealed partial class ContactGraph
    {
        /// <summary>The most manifolds one pair keeps (a convex shape against a mesh).</summary>
        public const int MaxManifoldsPerPair = 4;

        public Contact[] Contacts = new Contact[16];
        /// <summary>Live contact ids, densely packed (swap-remove keeps the order deterministic).</summary>
        public int[] Dense = new int[16];
        public int DenseCount;

        int _contactsUsed;
        int _contactFree = -1;             // free contacts chain through FirstManifold
        PairMap _map = new PairMap();

        // Edge e = 2 c + side (side 0: in ShapeA's list, 1: in ShapeB's list).
        int[] _edgeNext = new int[32];
        int[] _edgePrev = new int[32];
        int[] _shapeHead = Array.Empty<int>();

        /// <summary>Manifold pool; a contact's manifolds chain through <see cref="ManifoldNext"/>.</summary>
        public ContactManifold[] Manifolds = new ContactManifold[16];
        public int[] ManifoldNext = new int[16];
        /// <summary>Per manifold, its normal in shape A's frame (for reuse).</summary>
        public Vector3[] LocalNormal = new Vector3[16];
        /// <summary>Per manifold point (4 m + i), its point on shape A's surface in A's frame (for reuse).</summary>
        public Vector3[] LocalPointA = new Vector3[64];
        /// <summary>Per manifold point (4 m + i), its point on shape B's surface in B's frame (for reuse).</summary>
        public Vector3[] LocalPointB = new Vector3[64];
        /// <summary>Per manifold point (4 m + i), the pair function's separation minus what carrying the local points gives (for reuse).</summary>
        public float[] SeparationOffset = new float[64];
        int _manifoldsUsed;
        int _manifoldFree = -1;

        /// <summary>Live contacts.</summary>
        public int Count => DenseCount;

        /// <summary>The contact of a shape pair, or -1.</summary>
        public int Find(int shapeA, int shapeB) => _map.Find(PairMap.Key(shapeA, shapeB));

        /// <summary>Creates the contact of a pair not yet present (A must have the lower shape type).</summary>
        public int Create(int shapeA, int shapeB, int bodyA, int bodyB, bool sensor)
        {
            int c;
            if (_contactFree >= 0)
            {
                c = _contactFree;
                _contactFree = Contacts[c].FirstManifold;
            }
            else
            {
                if (_contactsUsed == Contacts.Length) GrowContacts();
                c = _contactsUsed++;
            }
            ulong key = PairMap.Key(shapeA, shapeB);
            Contacts[c] = new Contact
            {
                ShapeA = shapeA,
                ShapeB = shapeB,
                BodyA = bodyA,
                BodyB = bodyB,
                Key = key,
                FirstManifold = -1,
                DenseIndex = DenseCount,
                Flags = sensor ? ContactFlags.Sensor : ContactFlags.None,
            };
            Dense[DenseCount++] = c;
            _map.Add(key, c);
            LinkEdge(2 * c, shapeA);
            LinkEdge(2 * c + 1, shapeB);
            return c;
        }

        /// <summary>Destroys a contact and frees its manifolds.</summary>
        public void Destroy(int c)
        {
            ref Contact k = ref Contacts[c];
            _map.Remove(k.Key);
            UnlinkEdge(2 * c, k.ShapeA);
            UnlinkEdge(2 * c + 1, k.ShapeB);
            FreeManifolds(ref k);
            int at = k.DenseIndex;
            int last = Dense[--DenseCount];
            Dense[at] = last;
            Contacts[last].DenseIndex = at;
            k.DenseIndex = -1;
            k.FirstManifold = _contactFree;
            _contactFree = c;
        }

        /// <summary>The first edge in a shape's contact list, or -1.</summary>
        public int FirstEdge(int shape) => shape < _shapeHead.Length ? _shapeHead[shape] : -1;

        /// <summary>The next edge in the same shape's list, or -1.</summary>
        public int NextEdge(int edge) => _edgeNext[edge];

        /// <summary>Makes sure shape slots below <paramref name="shapeSlots"/> have a list head.</summary>
        public void EnsureShapeCapacity(int shapeSlots)
        {
            if (_shapeHead.Length >= shapeSlots) return;
            int old = _shapeHead.Length;
            Array.Resize(ref _shapeHead, Math.Max(shapeSlots, 2 * old));
            for (int i = old; i < _shapeHead.Length; i++) _shapeHead[i] = -1;
        }

        /// <summary>Sizes the pools for <paramref name="contacts"/> contacts and <paramref name="manifolds"/> manifolds.</summary>
        public void Reserve(int contacts, int manifolds)
        {
            while (Contacts.Length < contacts) GrowContacts();
            _map.Reserve(contacts);
            if (Manifolds.Length < manifolds)
            {
                Array.Resize(ref Manifolds, manifolds);
                Array.Resize(ref ManifoldNext, manifolds);
                Array.Resize(ref LocalNormal, manifolds);
                Array.Resize(ref LocalPointA, 4 * manifolds);
                Array.Resize(ref LocalPointB, 4 * manifolds);
                Array.Resize(ref SeparationOffset, 4 * manifolds);
            }
        }

        /// <summary>Takes a manifold from the pool (its contents are garbage).</summary>
        public int AllocateManifold()
        {
            if (_manifoldFree >= 0)
            {
                int m = _manifoldFree;
                _manifoldFree = ManifoldNext[m];
                ManifoldNext[m] = -1;
                return m;
            }
            if (_manifoldsUsed == Manifolds.Length)
            {
                Array.Resize(ref Manifolds, 2 * Manifolds.Length);
                Array.Resize(ref ManifoldNext, 2 * ManifoldNext.Length);
                Array.Resize(ref LocalNormal, Manifolds.Length);
                Array.Resize(ref LocalPointA, 4 * Manifolds.Length);
                Array.Resize(ref LocalPointB, 4 * Manifolds.Length);
                Array.Resize(ref SeparationOffset, 4 * Manifolds.Length);
            }
            ManifoldNext[_manifoldsUsed] = -1;
            return _manifoldsUsed++;
        }

        /// <summary>Returns a contact's manifolds to the pool.</summary>
        public void FreeManifolds(ref Contact k)
        {
            int m = k.FirstManifold;
            while (m >= 0)
            {
                int next = ManifoldNext[m];
                ManifoldNext[m] = _manifoldFree;
                _manifoldFree = m;
                m = next;
            }
            k.FirstManifold = -1;
            k.ManifoldCount = 0;
            k.Flags &= ~ContactFlags.Reusable;
        }

        void LinkEdge(int edge, int shape)
        {
            EnsureShapeCapacity(shape + 1);
            int head = _shapeHead[shape];
            _edgeNext[edge] = head;
            _edgePrev[edge] = -1;
            if (head >= 0) _edgePrev[head] = edge;
            _shapeHead[shape] = edge;
        }

        void UnlinkEdge(int edge, int shape)
        {
            int prev = _edgePrev[edge], next = _edgeNext[edge];
            if (prev >= 0) _edgeNext[prev] = next;
            else _shapeHead[shape] = next;
            if (next >= 0) _edgePrev[next] = prev;
        }

        void GrowContacts()
        {
            int n = 2 * Contacts.Length;
            Array.Resize(ref Contacts, n);
            Array.Resize(ref Dense, n);
            Array.Resize(ref _edgeNext, 2 * n);
            Array.Resize(ref _edgePrev, 2 * n);
        }
    }
}
