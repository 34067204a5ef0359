using System;
using Fulcrum.Collision;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// The <see cref="StepStage.Islands"/> stage and sleeping. Each step it
    /// <list type="number">
    /// <item>wakes sleeping islands that an awake body now touches (through a contact or a joint),</item>
    /// <item>lists the contacts and joints the solver must handle this step (those with an awake dynamic body),</item>
    /// <item>splits the awake dynamic bodies into islands by union-find over those constraints
    /// (static and kinematic bodies do not join islands: they do not pass forces on).</item>
    /// </list>
    /// After the solve, <see cref="UpdateSleep"/> advances each body's rest timer and puts to
    /// sleep every island whose bodies have all rested for TimeToSleep. A sleeping island's
    /// bodies are linked in a ring (<see cref="SleepNext"/>) so that waking any one of them
    /// wakes all, at a cost proportional to the island alone; while asleep they cost the solver
    /// nothing.
    /// </summary>
    internal sealed class IslandBuilder
    {
        /// <summary>Union-find parent per body slot (valid for awake dynamic bodies during a step).</summary>
        int[] _parent = Array.Empty<int>();
        /// <summary>Smallest rest time in each island, indexed by the root's slot.</summary>
        float[] _islandRest = Array.Empty<float>();
        int[] _ringHead = Array.Empty<int>();
        int[] _ringTail = Array.Empty<int>();

        /// <summary>Next body of the sleeping island's ring, per body slot; -1 when not in a ring.</summary>
        public int[] SleepNext = Array.Empty<int>();

        /// <summary>Indices (into the contact graph's manifold pool) of the manifolds the solver handles this step.</summary>
        public int[] Manifolds = Array.Empty<int>();
        public int ManifoldCount;

        /// <summary>Slots of the joints the solver handles this step.</summary>
        public int[] Joints = Array.Empty<int>();
        public int JointCount;

        /// <summary>Awake non-static bodies, in slot order of <see cref="SlotStorage.Active"/>.</summary>
        public int[] AwakeBodies = Array.Empty<int>();
        public int AwakeCount;

        /// <summary>Makes the per-slot arrays cover <paramref name="slots"/> body slots.</summary>
        public void EnsureBodies(int slots)
        {
            if (SleepNext.Length >= slots) return;
            int old = SleepNext.Length;
            int n = Math.Max(slots, Math.Max(16, old * 2));
            Array.Resize(ref SleepNext, n);
            Array.Resize(ref _parent, n);
            Array.Resize(ref _islandRest, n);
            Array.Resize(ref _ringHead, n);
            Array.Resize(ref _ringTail, n);
            for (int i = old; i < n; i++) SleepNext[i] = -1;
        }

        /// <summary>Takes the sleeping islands' rings of a restored state (a new builder only).</summary>
        public void RestoreSleepRings(int[] sleepNext)
        {
            EnsureBodies(sleepNext.Length);
            Array.Copy(sleepNext, SleepNext, sleepNext.Length);
        }

        /// <summary>Sizes the step arrays for <paramref name="bodies"/> body slots, <paramref name="manifolds"/> manifolds and <paramref name="joints"/> joints.</summary>
        public void Reserve(int bodies, int manifolds, int joints)
        {
            EnsureBodies(bodies);
            if (AwakeBodies.Length < bodies) AwakeBodies = new int[bodies];
            if (Manifolds.Length < manifolds) Manifolds = new int[manifolds];
            if (Joints.Length < joints) Joints = new int[joints];
        }

        /// <summary>Wakes body <paramref name="slot"/> and, if it sleeps in an island, the whole island.</summary>
        public void WakeIsland(BodyStorage b, int slot)
        {
            if (slot >= SleepNext.Length || SleepNext[slot] < 0) return;
            int k = slot;
            do
            {
                int next = SleepNext[k];
                SleepNext[k] = -1;
                b.Awake[k] = true;
                b.SleepTime[k] = 0;
                k = next;
            }
            while (k != slot && k >= 0);
        }

        static bool IsAwakeDynamic(BodyStorage b, int i) => b.Type[i] == BodyType.Dynamic && b.Awake[i];

        // A body that can push a sleeping neighbour awake: an awake dynamic body, or an awake
        // kinematic body that moves. A resting kinematic body leaves its neighbours asleep.
        static bool CanWake(BodyStorage b, int i) =>
            b.Awake[i] && (b.Type[i] == BodyType.Dynamic ||
                           (b.Type[i] == BodyType.Kinematic && (b.LinearVelocity[i] != System.Numerics.Vector3.Zero || b.AngularVelocity[i] != System.Numerics.Vector3.Zero)));

        bool WakePair(BodyStorage b, int x, int y)
        {
            if (x < 0 || y < 0) return false;
            if (b.Type[y] == BodyType.Dynamic && !b.Awake[y] && CanWake(b, x)) { Wake(b, y); return true; }
            if (b.Type[x] == BodyType.Dynamic && !b.Awake[x] && CanWake(b, y)) { Wake(b, x); return true; }
            return false;
        }

        void Wake(BodyStorage b, int i)
        {
            b.Awake[i] = true;
            b.SleepTime[i] = 0;
            WakeIsland(b, i);
        }

        /// <summary>Runs the islands stage over the contact set and the joints.</summary>
        public void Build(BodyStorage b, ShapeStorage shapes, ContactManifold[] manifolds, int[] source, int manifoldCount, JointStorage joints)
        {
            EnsureBodies(b.SlotCount);

            // 1. Wake islands touched by awake bodies, until nothing changes (normally one pass).
            bool woke = true;
            for (int pass = 0; woke && pass < 8; pass++)
            {
                woke = false;
                for (int k = 0; k < manifoldCount; k++)
                {
                    ref ContactManifold m = ref manifolds[source[k]];
                    if (!IsLiveContact(m, shapes)) continue;
                    woke |= WakePair(b, m.BodyA, m.BodyB);
                }
                for (int k = 0; k < joints.ActiveCount; k++)
                {
                    ref JointData j = ref joints.Data[joints.Active[k]];
                    if (j.Broken) continue;
                    woke |= WakePair(b, j.BodyA, j.BodyB);
                }
            }

            // 2. The awake bodies, each its own island to start with.
            AwakeCount = 0;
            if (AwakeBodies.Length < b.ActiveCount) AwakeBodies = new int[Math.Max(16, b.ActiveCount * 2)];
            for (int k = 0; k < b.ActiveCount; k++)
            {
                int i = b.Active[k];
                if (b.Type[i] == BodyType.Static || !b.Awake[i]) continue;
                AwakeBodies[AwakeCount++] = i;
                _parent[i] = i;
            }

            // 3. The constraints of this step, joined by union-find.
            ManifoldCount = 0;
            if (Manifolds.Length < manifoldCount) Manifolds = new int[Math.Max(16, manifoldCount * 2)];
            for (int k = 0; k < manifoldCount; k++)
            {
                int slot = source[k];
                ref ContactManifold m = ref manifolds[slot];
                if (!IsLiveContact(m, shapes)) continue;
                bool a = IsAwakeDynamic(b, m.BodyA), c = IsAwakeDynamic(b, m.BodyB);
                if (!a && !c) continue;
                Manifolds[ManifoldCount++] = slot;
                if (a && c) Union(m.BodyA, m.BodyB);
            }
            JointCount = 0;
            if (Joints.Length < joints.ActiveCount) Joints = new int[Math.Max(16, joints.ActiveCount * 2)];
            for (int k = 0; k < joints.ActiveCount; k++)
            {
                int slot = joints.Active[k];
                ref JointData j = ref joints.Data[slot];
                if (j.Broken) continue;
                bool a = j.BodyA >= 0 && IsAwakeDynamic(b, j.BodyA), c = j.BodyB >= 0 && IsAwakeDynamic(b, j.BodyB);
                if (!a && !c) continue;
                Joints[JointCount++] = slot;
                if (a && c) Union(j.BodyA, j.BodyB);
            }
        }

        static bool IsLiveContact(in ContactManifold m, ShapeStorage shapes) =>
            m.PointCount > 0 && m.BodyA >= 0 && m.BodyB >= 0 && !shapes.IsSensor[m.ShapeA] && !shapes.IsSensor[m.ShapeB];

        int Find(int i)
        {
            while (_parent[i] != i)
            {
                _parent[i] = _parent[_parent[i]];
                i = _parent[i];
            }
            return i;
        }

        void Union(int x, int y)
        {
            int rx = Find(x), ry = Find(y);
            if (rx == ry) return;
            // The smaller slot becomes the root: the result does not depend on visiting order.
            if (rx < ry) _parent[ry] = rx; else _parent[rx] = ry;
        }

        /// <summary>
        /// The sleep half of <see cref="StepStage.SleepAndEvents"/>: rest timers, then islands
        /// whose every body has rested for TimeToSleep go to sleep (velocities
        /// zeroed, bodies linked in a ring). An island touching a moving kinematic body stays awake.
        /// </summary>
        public void UpdateSleep(BodyStorage b, ContactManifold[] manifolds, JointStorage joints, in WorldSettings s, float dt)
        {
            float linTol2 = s.SleepLinearVelocity * s.SleepLinearVelocity;
            float angTol2 = s.SleepAngularVelocity * s.SleepAngularVelocity;
            for (int k = 0; k < AwakeCount; k++)
            {
                int i = AwakeBodies[k];
                if (!b.Awake[i]) continue;
                if (!b.AllowSleep[i] || b.LinearVelocity[i].LengthSquared() > linTol2 || b.AngularVelocity[i].LengthSquared() > angTol2)
                    b.SleepTime[i] = 0;
                else
                    b.SleepTime[i] += dt;
            }
            if (!s.EnableSleeping) return;

            for (int k = 0; k < AwakeCount; k++)
            {
                int i = AwakeBodies[k];
                if (b.Type[i] != BodyType.Dynamic) continue;
                _islandRest[i] = float.MaxValue;
                _ringHead[i] = -1;
            }
            for (int k = 0; k < AwakeCount; k++)
            {
                int i = AwakeBodies[k];
                if (b.Type[i] != BodyType.Dynamic) continue;
                int r = Find(i);
                _islandRest[r] = Math.Min(_islandRest[r], b.SleepTime[i]);
            }
            // A moving kinematic body keeps what it touches awake.
            for (int k = 0; k < ManifoldCount; k++)
            {
                ref ContactManifold m = ref manifolds[Manifolds[k]];
                HoldAwake(b, m.BodyA, m.BodyB);
                HoldAwake(b, m.BodyB, m.BodyA);
            }
            for (int k = 0; k < JointCount; k++)
            {
                ref JointData j = ref joints.Data[Joints[k]];
                if (j.BodyA >= 0 && j.BodyB >= 0)
                {
                    HoldAwake(b, j.BodyA, j.BodyB);
                    HoldAwake(b, j.BodyB, j.BodyA);
                }
            }

            for (int k = 0; k < AwakeCount; k++)
            {
                int i = AwakeBodies[k];
                if (b.Type[i] == BodyType.Kinematic)
                {
                    if (b.SleepTime[i] >= s.TimeToSleep) Sleep(b, i);
                    continue;
                }
                int r = Find(i);
                if (_islandRest[r] < s.TimeToSleep) continue;
                // Link the island's bodies into a ring.
                if (_ringHead[r] < 0)
                {
                    _ringHead[r] = i;
                    _ringTail[r] = i;
                }
                else
                {
                    SleepNext[i] = _ringHead[r];
                    _ringHead[r] = i;
                }
            }
            for (int k = 0; k < AwakeCount; k++)
            {
                int i = AwakeBodies[k];
                if (b.Type[i] != BodyType.Dynamic || _parent[i] != i || _ringHead[i] < 0) continue;
                SleepNext[_ringTail[i]] = _ringHead[i];
                for (int x = _ringHead[i]; ; x = SleepNext[x])
                {
                    Sleep(b, x);
                    if (x == _ringTail[i]) break;
                }
            }
        }

        void HoldAwake(BodyStorage b, int kinematic, int other)
        {
            if (kinematic < 0 || other < 0 || b.Type[kinematic] != BodyType.Kinematic || b.Type[other] != BodyType.Dynamic) return;
            if (b.SleepTime[kinematic] > 0) return; // resting kinematic body
            if (b.Awake[other]) _islandRest[Find(other)] = 0;
        }

        static void Sleep(BodyStorage b, int i)
        {
            b.Awake[i] = false;
            b.LinearVelocity[i] = default;
            b.AngularVelocity[i] = default;
        }
    }
}
