using System;
using System.Numerics;
using Fulcrum.Collision;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Shock propagation (Guendelman, Bridson and Fedkiw 2003, "Nonconvex rigid bodies with
    /// stacking"; Erleben 2005): after the biased passes of a TGS substep (after the velocity
    /// passes of a PGS step), the contacts are swept
    /// once from the ground up, each treating its lower body as immovable and removing the
    /// approach of its points' centroid by moving the upper body along the vertical (see
    /// SweepManifold for why not point by point, nor along the normal). A Gauss-Seidel row sees a heavy body through the
    /// light body's effective mass, so it corrects the heavy body's approach by only m / M per
    /// pass and a 1000 kg box sinks into a 1 kg box (Documentation~/MassRatio.md); the sweep
    /// carries the ground's support up a stack in one pass whatever the masses.
    /// <para>
    /// Levels: fixed bodies are level 0, and a dynamic body is one more than the lowest body it
    /// touches or reaches within the step at its present approach (breadth-first over those
    /// contacts). A contact between bodies of
    /// different levels is swept, lower levels first; contacts within a level (side by side)
    /// and bodies with no path to a fixed body are left to the solver. The sweep acts only on
    /// contacts pressed deeper than WorldSettings.ShockDepth, where the soft contact would
    /// otherwise go on sinking, and speculatively on those the substep's approach would carry
    /// past it: a body resting at its usual depth (0.14 mm for a box on a box) is the solver's
    /// alone, and the sweep is a floor under heavy loads, which a landing stops at. It only removes
    /// approach and never pushes apart, so it takes energy out and never puts any in; its
    /// impulses are not accumulated (warm starting and reported impulses are the solver's).
    /// </para>
    /// </summary>
    /// <summary>What one <see cref="ShockPropagation.Sweep"/> does: TGS's whole sweep per substep, or one of PGS's two.</summary>
    internal enum SweepPass : byte
    {
        /// <summary>Pushes and friction for the pushes and the load carried from the last sweep (TGS).</summary>
        Whole,
        /// <summary>Pushes only, passing each body's load down to the bodies under it (PGS, first sweep).</summary>
        Pushes,
        /// <summary>What approach is left, then friction for both sweeps' pushes and the loads (PGS, second sweep).</summary>
        Friction,
    }

    internal sealed class ShockPropagation
    {
        /// <summary>
        /// One swept contact (a manifold), from the lower body to the upper one. The sweep acts
        /// on the centroid of the manifold's points (see SweepManifold), whose separation and
        /// normal speed are linear in the point: the mean arms' angular terms stand for the points'.
        /// </summary>
        struct Row
        {
            public int Upper, Lower;
            public Vector3 Normal;      // unit, from the lower body to the upper one
            public Vector3 AngularU;    // mean of rU x n over the points
            public Vector3 AngularL;    // mean of rL x n over the points
            public float Separation;    // mean over the points, at the start of the step
            public float Friction;      // the manifold's coefficient
            public float Pushed;        // normal impulse of the first of PGS's two sweeps, N s
            public float Held;          // the contacts' own friction impulse in the last step, N s (its magnitude)
            public float Carry;         // normal impulse this row's sweep put on the lower body, N s (0: none)
            public float CarryMass;     // the mass it rests on the lower body with, kg
        }

        Row[] _rows = new Row[64];
        Row[] _sorted = new Row[64];
        int _count;
        int[] _level = new int[16];
        int[] _degree = new int[17];
        int[] _adjacency = new int[32];
        int[] _queue = new int[16];
        int[] _levelStart = new int[17];
        // The sweep's parallel items: per level, the first row of each upper body in it, and
        // per row the next row of the same upper body (-1: none). A level's rows change only
        // their upper bodies (the levels differ by one across every row), so the chains of one
        // level are independent and each runs in order.
        int[] _heads = new int[16];
        int[] _headStart = new int[17];
        int[] _next = new int[16];
        int[] _lastRowOf = new int[16];
        int _levels;
        readonly SweepJob _job;

        public ShockPropagation() => _job = new SweepJob(this);
        // Per manifold of the step's list: whether its pair touches (Build's three passes ask).
        bool[] _touches = new bool[16];
        // Per solver body: the normal impulse the sweep's pushes on the bodies it carries put on
        // it in the last substep (carried down the stack; the rows' Carry summed).
        float[] _carried = new float[16];
        // The same for the mass a body carries (the bodies resting on it, and theirs), kg: its
        // friction must stop them with it.
        float[] _carriedMass = new float[16];

        /// <summary>cos 45 degrees: the steepest contact that carries support in the sweep.</summary>
        const float SupportCosine = 0.7071f;

        /// <summary>cos 5 degrees: a contact tilted less than this is pushed along the vertical.</summary>
        const float LevelCosine = 0.9962f;

        /// <summary>Capacity for <paramref name="bodies"/> solver bodies and <paramref name="manifolds"/> manifolds.</summary>
        public void Reserve(int bodies, int manifolds)
        {
            if (_level.Length < bodies) _level = new int[bodies];
            if (_carried.Length < bodies)
            {
                _carried = new float[bodies];
                _carriedMass = new float[bodies];
            }
            if (_queue.Length < bodies) _queue = new int[bodies];
            if (_degree.Length < bodies + 1) _degree = new int[bodies + 1];
            if (_levelStart.Length < bodies + 2) _levelStart = new int[bodies + 2];
            if (_headStart.Length < bodies + 2) _headStart = new int[bodies + 2];
            if (_lastRowOf.Length < bodies) _lastRowOf = new int[bodies];
            if (_heads.Length < manifolds) _heads = new int[manifolds];
            if (_next.Length < manifolds) _next = new int[manifolds];
            if (_adjacency.Length < 2 * manifolds) _adjacency = new int[2 * manifolds];
            if (_touches.Length < manifolds) _touches = new bool[manifolds];
            if (_rows.Length < manifolds)
            {
                _rows = new Row[manifolds];
                _sorted = new Row[manifolds];
            }
        }

        /// <summary>The most upper bodies one level has had in any step (the sweep's parallel items; for tests).</summary>
        public int WidestLevel;

        /// <summary>Rows in the current step.</summary>
        public int RowCount => _count;

        /// <summary>
        /// Levels the step's bodies and collects the rows of the contacts between levels, in a
        /// step where some contact is within half of <paramref name="depth"/> (m) of the depth
        /// or approaches fast enough to reach it in <paramref name="dt"/> (s); otherwise none.
        /// <paramref name="touching"/>: a point closer than this (m), now or at the end of the
        /// step at the bodies' present approach, makes its pair touch.
        /// </summary>
        public void Build(SolverBody[] bodies, int bodyCount, ContactManifold[] manifolds, int[] manifoldList, int manifoldCount,
            int[] indexOfSlot, float touching, float depth, float dt)
        {
            _count = 0;
            Levelled = false;
            // Solver body indices are the step's own: nothing carried from the last step.
            if (_carried.Length < bodyCount)
            {
                _carried = new float[2 * bodyCount];
                _carriedMass = new float[2 * bodyCount];
            }
            else
            {
                Array.Clear(_carried, 0, bodyCount);
                Array.Clear(_carriedMass, 0, bodyCount);
            }
            // Only a contact that is half way to the depth already, or that would get there
            // within the step at its present approach, can pass it: a step with none (every
            // ordinary stack at rest) pays this one pass over the points and nothing else.
            float candidate = -0.5f * depth;
            bool any = false;
            for (int k = 0; k < manifoldCount && !any; k++)
                any = Candidate(ref manifolds[manifoldList[k]], bodies, indexOfSlot, candidate, dt);
            if (!any) return;
            if (_level.Length < bodyCount) _level = new int[2 * bodyCount];
            if (_degree.Length < bodyCount + 1) _degree = new int[2 * bodyCount + 1];
            if (_queue.Length < bodyCount) _queue = new int[2 * bodyCount];
            if (_adjacency.Length < 2 * manifoldCount) _adjacency = new int[4 * manifoldCount];
            if (_touches.Length < manifoldCount) _touches = new bool[2 * manifoldCount];
            const int Unreached = int.MaxValue;

            // Adjacency of touching pairs in compressed rows (degree counts, prefix sums, fill).
            Array.Clear(_degree, 0, bodyCount + 1);
            for (int k = 0; k < manifoldCount; k++)
            {
                ref ContactManifold m = ref manifolds[manifoldList[k]];
                _touches[k] = Touches(ref m, bodies, indexOfSlot, touching, dt);
                if (!_touches[k]) continue;
                _degree[IndexOf(indexOfSlot, m.BodyA) + 1]++;
                _degree[IndexOf(indexOfSlot, m.BodyB) + 1]++;
            }
            for (int i = 0; i < bodyCount; i++) _degree[i + 1] += _degree[i];
            for (int k = 0; k < manifoldCount; k++)
            {
                if (!_touches[k]) continue;
                ref ContactManifold m = ref manifolds[manifoldList[k]];
                int a = IndexOf(indexOfSlot, m.BodyA), b = IndexOf(indexOfSlot, m.BodyB);
                _adjacency[_degree[a]++] = b;
                _adjacency[_degree[b]++] = a;
            }
            // The fill advanced each start to the next one's: shift back.
            for (int i = bodyCount; i > 0; i--) _degree[i] = _degree[i - 1];
            _degree[0] = 0;

            int head = 0, tail = 0;
            for (int i = 0; i < bodyCount; i++)
            {
                if (bodies[i].IsDynamic == 0)
                {
                    _level[i] = 0;
                    _queue[tail++] = i;
                }
                else _level[i] = Unreached;
            }
            int maxLevel = 0;
            while (head < tail)
            {
                int i = _queue[head++];
                int next = _level[i] + 1;
                for (int e = _degree[i]; e < _degree[i + 1]; e++)
                {
                    int j = _adjacency[e];
                    if (_level[j] != Unreached) continue;
                    _level[j] = next;
                    maxLevel = Math.Max(maxLevel, next);
                    _queue[tail++] = j;
                }
            }

            for (int k = 0; k < manifoldCount; k++)
            {
                ref ContactManifold m = ref manifolds[manifoldList[k]];
                // Every touching contact: a contact resting now may be pressed past the depth
                // within the step by a body landing on the one above it.
                if (!_touches[k] || m.PointCount == 0) continue;
                int a = IndexOf(indexOfSlot, m.BodyA), b = IndexOf(indexOfSlot, m.BodyB);
                int la = _level[a], lb = _level[b];
                if (la == lb || la == Unreached || lb == Unreached) continue;
                bool aLower = la < lb;
                int upper = aLower ? b : a, lower = aLower ? a : b;
                ref SolverBody u = ref bodies[upper];
                if (u.IsDynamic == 0) continue;
                Vector3 n = aLower ? m.Normal : -m.Normal;
                if (_rows.Length == _count)
                {
                    Array.Resize(ref _rows, 2 * _count);
                    _sorted = new Row[_rows.Length];
                }
                Vector3 armU = Vector3.Zero, armL = Vector3.Zero;
                float separation = 0, tangent1 = 0, tangent2 = 0;
                for (int p = 0; p < m.PointCount; p++)
                {
                    ref ContactPoint cp = ref ContactManifold.Point(ref m, p);
                    armU += aLower ? cp.AnchorB : cp.AnchorA;
                    armL += aLower ? cp.AnchorA : cp.AnchorB;
                    separation += cp.Separation;
                    tangent1 += cp.TangentImpulse1;
                    tangent2 += cp.TangentImpulse2;
                }
                float inverseCount = 1f / m.PointCount;
                ref Row r = ref _rows[_count];
                r.Upper = upper;
                r.Lower = lower;
                r.Normal = n;
                // The centroid's arms: r x n is linear in r.
                r.AngularU = Vector3.Cross(armU * inverseCount, n);
                r.AngularL = Vector3.Cross(armL * inverseCount, n);
                r.Separation = separation * inverseCount;
                r.Friction = m.Friction;
                r.Held = MathF.Sqrt(tangent1 * tangent1 + tangent2 * tangent2);
                _count++;
            }

            Levelled = true;
            // Lower levels first (a counting sort keeps the manifolds' order within a level).
            if (_levelStart.Length < maxLevel + 2) _levelStart = new int[2 * maxLevel + 2];
            Array.Clear(_levelStart, 0, maxLevel + 2);
            for (int k = 0; k < _count; k++) _levelStart[_level[_rows[k].Lower] + 1]++;
            for (int l = 0; l <= maxLevel; l++) _levelStart[l + 1] += _levelStart[l];
            for (int k = 0; k < _count; k++) _sorted[_levelStart[_level[_rows[k].Lower]]++] = _rows[k];
            // _levelStart[l] is now the end of level l's rows. Chain each level's rows by upper body.
            if (_heads.Length < _count)
            {
                _heads = new int[_sorted.Length];
                _next = new int[_sorted.Length];
            }
            if (_lastRowOf.Length < bodyCount) _lastRowOf = new int[2 * bodyCount];
            if (_headStart.Length < maxLevel + 2) _headStart = new int[2 * maxLevel + 2];
            for (int k = 0; k < _count; k++) _lastRowOf[_sorted[k].Upper] = -1;
            int heads = 0, row = 0;
            _levels = maxLevel + 1;
            for (int l = 0; l <= maxLevel; l++)
            {
                _headStart[l] = heads;
                for (; row < _levelStart[l]; row++)
                {
                    _next[row] = -1;
                    int upper = _sorted[row].Upper;
                    if (_lastRowOf[upper] < 0) _heads[heads++] = row;
                    else _next[_lastRowOf[upper]] = row;
                    _lastRowOf[upper] = row;
                }
            }
            _headStart[_levels] = heads;
            for (int l = 0; l < _levels; l++) WidestLevel = Math.Max(WidestLevel, _headStart[l + 1] - _headStart[l]);
        }

        static int IndexOf(int[] indexOfSlot, int slot) => slot < 0 ? 0 : indexOfSlot[slot];

        /// <summary>Whether the last <see cref="Build"/> levelled the bodies (it does only where a contact may pass the depth).</summary>
        public bool Levelled { get; private set; }

        /// <summary>
        /// The level of solver body <paramref name="k"/> in the last <see cref="Build"/> (0: fixed;
        /// int.MaxValue: no path to a fixed body); valid while <see cref="Levelled"/>.
        /// </summary>
        public int LevelOf(int k) => _level[k];

        // Touching now, or by the end of the step at the centres' present approach: a body
        // landing within the step is levelled and swept in it (levelled only once it touched,
        // a 1 t box landing on two stacked 1 kg boxes went 13 mm into the top one in its
        // landing step, and the sweep, which never pushes apart, kept it there).
        static bool Touches(ref ContactManifold m, SolverBody[] bodies, int[] indexOfSlot, float touching, float dt) =>
            Candidate(ref m, bodies, indexOfSlot, touching, dt);

        // Deeper than the candidate depth now, or at the end of the step at the centres'
        // present approach speed along the normal.
        static bool Candidate(ref ContactManifold m, SolverBody[] bodies, int[] indexOfSlot, float candidate, float dt)
        {
            float approach = Vector3.Dot(m.Normal, bodies[IndexOf(indexOfSlot, m.BodyB)].LinearVelocity - bodies[IndexOf(indexOfSlot, m.BodyA)].LinearVelocity);
            return Deeper(ref m, candidate - MathF.Min(approach, 0f) * dt);
        }

        static bool Deeper(ref ContactManifold m, float separation)
        {
            for (int p = 0; p < m.PointCount; p++)
                if (ContactManifold.Point(ref m, p).Separation < separation) return true;
            return false;
        }

        /// <summary>
        /// The sweep: removes each upper body's approach to its lower body where their contact
        /// is deeper than <paramref name="depth"/> (m), and cuts it where it would carry the
        /// contact past that depth within the substep of <paramref name="h"/> (s), lower levels
        /// first, the lower body held still. <paramref name="up"/>: the unit vector against
        /// gravity, or zero without gravity. <paramref name="maxPush"/> (m/s): the fastest a
        /// dynamic lower body carries the upper one away. <paramref name="gravity"/>: |g| (m/s²)
        /// for the weight's friction on pressed contacts (PGS), or 0.
        /// </summary>
        public void Sweep(SolverBody[] bodies, float depth, Vector3 up, float h, float maxPush, float gravity = 0f, SweepPass pass = SweepPass.Whole,
            IParallelScheduler? pool = null)
        {
            if (_count == 0) return;
            int n = bodies.Length;
            if (_carried.Length < n)
            {
                Array.Resize(ref _carried, n);
                Array.Resize(ref _carriedMass, n);
            }
            SweepJob job = _job;
            job.Bodies = bodies;
            job.Depth = depth;
            job.Up = up;
            job.H = h;
            job.MaxPush = maxPush;
            job.Gravity = gravity;
            job.Pass = pass;
            // Level by level (each reads the velocities the level below it left), the upper
            // bodies of a level side by side.
            for (int l = 0; l < _levels; l++)
            {
                if (pool != null) pool.For(job, _headStart[l], _headStart[l + 1], MinChunk);
                else job.Execute(_headStart[l], _headStart[l + 1]);
            }
            job.Bodies = null;
            // What each body carried in this substep is what the next one's friction below it
            // may use: the loads its rows put on it, summed in row order (the same sums whatever
            // thread swept which row). Read in the sweep above, replaced only now.
            int k;
            for (k = 0; k < _count; k++)
            {
                ref Row r = ref _sorted[k];
                _carried[r.Upper] = 0f;
                _carried[r.Lower] = 0f;
                _carriedMass[r.Upper] = 0f;
                _carriedMass[r.Lower] = 0f;
            }
            for (k = 0; k < _count; k++)
            {
                ref Row r = ref _sorted[k];
                if (!(r.Carry > 0f)) continue;
                _carried[r.Lower] += r.Carry;
                _carriedMass[r.Lower] += r.CarryMass;
            }
        }

        // The approach of the manifold's centroid (the mean of its points' separations and normal
        // speeds, both linear in the point) is removed by moving the upper body along the normal
        // only. Removing it point by point spins the body a little each substep (the corners are
        // not symmetric in a Gauss-Seidel order), and a tower drifts sideways on that spin; the
        // rotation of a resting body is the solver's, the sinking the sweep's.
        void SweepManifold(SolverBody[] bodies, ref Row first, float depth, Vector3 up, float h, float maxPush, float gravity, SweepPass pass)
        {
            Vector3 n = first.Normal;
            // Under gravity the sweep carries support: a contact more than 45 degrees off the
            // vertical is left to the solver, and within 5 degrees of level the approach is taken
            // out along the vertical, so a slightly tilted normal does not nudge the body sideways
            // every substep (a 40-row pyramid drifts twice as far when the push follows the normal).
            float lift = 1f;
            first.Carry = 0f;
            if (up != Vector3.Zero)
            {
                lift = Vector3.Dot(n, up);
                if (lift < SupportCosine) return;
            }
            float cosine = lift;
            ref SolverBody u = ref bodies[first.Upper];
            ref SolverBody l = ref bodies[first.Lower];
            float linear = Vector3.Dot(n, u.LinearVelocity - l.LinearVelocity);
            float drift = Vector3.Dot(n, u.DeltaPosition - l.DeltaPosition);
            // The centroid's separation at the pose now (ContactSolver's first-order update)
            // and its normal speed.
            float s = first.Separation + Vector3.Dot(u.DeltaAngle, first.AngularU) - Vector3.Dot(l.DeltaAngle, first.AngularL) + drift;
            float vn = Vector3.Dot(first.AngularU, u.AngularVelocity) - Vector3.Dot(first.AngularL, l.AngularVelocity) + linear;
            // Within the depth the soft contact rests as it would without the sweep; deeper, the
            // sweep holds it where it is. Speculatively: an approach that would carry the
            // centroid past the depth within this substep is cut to what reaches it, so a fast
            // landing stops at the depth instead of a substep's travel beyond it (which nothing
            // pushes back out: the soft contact lifts the heavy body through the light one's
            // effective mass).
            float allowed = MathF.Max(0f, s + depth) / h;
            // Along the vertical under gravity where the contact is within a few degrees of level
            // (along the normal otherwise, and without gravity): the push that leaves the approach
            // at the allowed one. A vertical push on a tilted contact moves the body up the slope
            // by sin(tilt) of it, which held a 300:1 stack dead on a 25 degree ramp it should
            // slide down (mu 0.3).
            bool level = up != Vector3.Zero && lift >= LevelCosine;
            Vector3 along = level ? up : n;
            if (!level) lift = 1f;
            float push = vn >= -allowed ? 0f : -(vn + allowed) / lift;
            // A dynamic lower body is held still only as a support: the push may stop the upper
            // body's motion toward it, and carry it along with the lower body at no more than a
            // contact's push-out speed (WorldSettings.MaxContactPushSpeed), not hand it the lower
            // body's own speed (a 0.35 kg body flying at 88 m/s into an 8 t one gave it 1.3e7 J,
            // fuzz seed 4299). A fixed body (static, or kinematic: its motion is prescribed)
            // carries the upper one along at its own speed.
            if (l.IsDynamic != 0)
                push = MathF.Min(push, Math.Clamp(Vector3.Dot(l.LinearVelocity, along), 0f, maxPush) - Vector3.Dot(u.LinearVelocity, along));
            if (push > 0f)
            {
                u.LinearVelocity += push * along;
                // A body with locked translation axes does not move along them (AxisLocks).
                if (u.HasLinearLocks) u.LinearVelocity = AxisLockMath.MaskLinear(u.LinearVelocity, u.Locks);
            }
            // Friction for the load the sweep carries. Its pushes stand in for the normal impulse
            // the soft contacts could not carry (a 1 kg box under a 1000 kg crate takes about 29 kg
            // of it), so friction bounded by the contacts' own impulses held too little: a 100:1
            // or 1000:1 stack on a 25 degree ramp (mu 0.6) crept 14-65 mm in 4 s under TGS and slid
            // 1.3-2.4 m under PGS. The upper body's sliding on the lower one (held still) is taken
            // out up to mu times the normal impulse of its own push plus what it carried in the
            // last substep (the pushes on the bodies above it, passed down).
            float mass = u.InverseMass > 0f ? 1f / u.InverseMass : 0f;
            float pushed = push * mass * Vector3.Dot(along, n);
            if (pass == SweepPass.Pushes) first.Pushed = pushed;
            else if (pass == SweepPass.Friction) pushed += first.Pushed;
            float normal = pushed + _carried[first.Upper];
            // The weight pressing the contact: the upper body and the mass resting on it (the
            // last sweep's count), along the normal. (The pushes passed down from the bodies
            // above stood in for it and came short of it: a 1000:1 stack's light box, on a 25
            // degree ramp at mu 0.6, had 111 N s of its 148 and crept down.)
            float load = (mass + _carriedMass[first.Upper]) * gravity * h * cosine;
            // PGS (gravity > 0 given): a contact pressed past half the depth carries the upper
            // body's weight, whatever its velocity passes already took of the approach (they take
            // most of it, and the push is the remainder): friction for at least that load. A
            // 100:1 or 1000:1 stack on a 15 or 25 degree ramp slid 18-700 mm in 4 s on the push
            // alone. TGS leaves it out: its biased passes leave the sweep the approach to take,
            // and with the weight the ragdoll pile no longer fell asleep.
            bool whole = pass == SweepPass.Friction && s <= -0.5f * depth;
            if (whole) normal = load;
            if (normal > 0f)
            {
                first.Carry = normal;
                first.CarryMass = mass + _carriedMass[first.Upper];
            }
            // The first of PGS's two sweeps only pushes and passes the loads down; the second
            // gives friction once, for the whole load (twice, it stopped a stack on a ramp
            // steeper than its friction).
            if (pass == SweepPass.Pushes) return;
            if (!(normal > 0f) || first.Friction <= 0f || mass == 0f) return;
            Vector3 relative = u.LinearVelocity - l.LinearVelocity;
            Vector3 slide = relative - Vector3.Dot(relative, n) * n;
            float speed = slide.Length();
            if (speed < 1e-9f) return;
            // The impulse mu N stops the upper body together with the load resting on it (which
            // its own contacts then keep with it): spent on the upper body alone, it would stop a
            // 1 kg box under a heavy load dead on any ramp, however steep for its friction.
            float bound = first.Friction * normal;
            // PGS, for the whole weight: the velocity passes' own friction (the contacts'
            // impulse, as stored at the last step's end) already spent part of that cone; the
            // sweep gives the rest, so that the two together stay within mu times the load.
            // Counted twice, a 10:1 to 1e4:1 stack on a 25 degree ramp at mu 0.3 slid 0.22-1.03 m
            // in 2 s where the closed form is 2.96. (For pushes and carried loads alone the
            // contacts carried none of that normal impulse, nor its friction.)
            if (whole) bound = MathF.Max(0f, bound - first.Held);
            float stop = MathF.Min(speed, bound / (mass + _carriedMass[first.Upper]));
            Vector3 change = -(stop / speed) * slide;
            // On a dynamic lower body (held still only as a support) the friction may slow the upper
            // body, not drag it along: pulled out from under a crate, a light box would otherwise
            // carry the crate with it for nothing (the box feels no reaction). A fixed lower body
            // (static, or kinematic: a conveyor) carries it along.
            if (l.IsDynamic != 0 && Vector3.Dot(change, u.LinearVelocity) > 0f) return;
            u.LinearVelocity += change;
            if (u.HasLinearLocks) u.LinearVelocity = AxisLockMath.MaskLinear(u.LinearVelocity, u.Locks);
        }

        /// <summary>Rows (upper-body chains) a thread takes at a time.</summary>
        const int MinChunk = 64;

        /// <summary>The rows of the upper-body chains [start, end) of one level, each chain in order.</summary>
        sealed class SweepJob : IParallelJob
        {
            readonly ShockPropagation _s;
            public SolverBody[]? Bodies;
            public float Depth, H, MaxPush, Gravity;
            public Vector3 Up;
            public SweepPass Pass;

            public SweepJob(ShockPropagation s) => _s = s;

            public void Execute(int start, int end)
            {
                ShockPropagation s = _s;
                SolverBody[] bodies = Bodies!;
                for (int i = start; i < end; i++)
                    for (int k = s._heads[i]; k >= 0; k = s._next[k])
                        s.SweepManifold(bodies, ref s._sorted[k], Depth, Up, H, MaxPush, Gravity, Pass);
            }
        }
    }
}
