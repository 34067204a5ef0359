using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// The solver's working set for one step: the solver bodies (a compact copy of the bodies
    /// that take part in constraints), the contact constraints and their points, the step's
    /// joints, all ordered by colour (<see cref="ConstraintColoring"/>), and the passes that
    /// <see cref="PgsSolver"/> and <see cref="TgsSolver"/> compose: integrate, warm start,
    /// solve, relax, restitution, position correction, write-back. Every array is kept from
    /// step to step and grows only when a step needs more: a steady step allocates nothing.
    /// </summary>
    internal sealed class SolverContext
    {
        const int Buckets = ConstraintColoring.MaxColors + 1;

        // Solver bodies; index 0 is the fixed body.
        public SolverBody[] Bodies = new SolverBody[16];
        public int BodyCount;
        /// <summary>Body slot of each solver body (index 0: -1).</summary>
        public int[] BodySlot = new int[16];
        Vector3[] _startCenter = new Vector3[16];
        Quaternion[] _startRotation = new Quaternion[16];
        int[] _indexOfSlot = Array.Empty<int>();
        ulong[] _colorMask = new ulong[16];

        // Constraints in colour order.
        public ContactConstraint[] Contacts = new ContactConstraint[16];
        public int ContactCount;
        public ContactConstraintPoint[] Points = new ContactConstraintPoint[64];
        public int PointCount;
        public int[] JointOrder = new int[16];
        public int JointCount;
        readonly int[] _contactStart = new int[Buckets + 1];
        readonly int[] _jointStart = new int[Buckets + 1];
        readonly int[] _pointCursor = new int[Buckets];
        readonly int[] _contactCursor = new int[Buckets];
        readonly int[] _jointCursor = new int[Buckets];
        int[] _color = new int[16];

        // The step.
        BodyStorage _storage = null!;
        JointStorage _joints = null!;
        ContactManifold[] _manifolds = Array.Empty<ContactManifold>();
        WorldSettings _settings;
        float _dt, _h, _invH;
        float _previousDt;
        Softness _contactSoftness, _fixedSoftness;
        JointSolver.StepParameters _jointParameters;
        readonly ColorJob _colorJob;
        readonly BodyJob _bodyJob;
        readonly ShockPropagation _shock = new ShockPropagation();

        // Contacts of each colour not taken by the wide path, by index into Contacts.
        int[] _scalarContacts = new int[16];
        readonly int[] _scalarStart = new int[Buckets + 1];
        // Wide groups (net10): per colour a range of groups of Vector<float>.Count manifolds.
        readonly int[] _wideStart = new int[Buckets + 1];
        int _wideGroups;
#if NET
        WideContact[] _wide = Array.Empty<WideContact>();
        WideImpact[] _wideImpact = Array.Empty<WideImpact>();
        int[] _wideManifold = Array.Empty<int>();
        int[] _rejected = Array.Empty<int>();
        readonly int[] _rejectedStart = new int[Buckets + 1];
        readonly int[] _wideCursor = new int[Buckets];
        int[] _wideBodies = Array.Empty<int>();
        int[] _wideSlots = Array.Empty<int>();
        int[] _wideSource = Array.Empty<int>();
#endif

        /// <summary>Wide groups of the last step (for tests and profiling).</summary>
        public int WideGroupCount => _wideGroups;

        /// <summary>Whether the wide (SIMD) contact path may take four-point manifolds (net10 with SIMD hardware).</summary>
        public bool WideContacts = true;

        /// <summary>Threads for the colour batches; null runs everything on the caller's thread.</summary>
        public WorkerPool? Pool;

        public SolverContext()
        {
            _colorJob = new ColorJob(this);
            _bodyJob = new BodyJob(this);
        }

        /// <summary>The (sub)step of the current solve, s.</summary>
        public float SubstepDt => _h;

        /// <summary>The settings of the current step.</summary>
        public ref readonly WorldSettings Settings => ref _settings;

        /// <summary>The body storage of the current step.</summary>
        public BodyStorage Storage => _storage;

        /// <summary>True when a contact of the step has restitution.</summary>
        public bool HasRestitution;

        /// <summary>True when the step has any constraint to solve.</summary>
        public bool HasWork => ContactCount > 0 || JointCount > 0 || _wideGroups > 0;

        /// <summary>
        /// Gives every body that a step constraint touches a solver index (static bodies and
        /// sleeping kinematic ones share the fixed index 0) and starts the step.
        /// </summary>
        public void Begin(BodyStorage storage, JointStorage joints, ContactManifold[] manifolds, IslandBuilder islands,
            in WorldSettings settings, float dt, int substeps)
        {
            _storage = storage;
            _joints = joints;
            _manifolds = manifolds;
            _settings = settings;
            _dt = dt;
            _h = dt / substeps;
            _invH = 1f / _h;
            if (_previousDt <= 0) _previousDt = dt;
            if (_indexOfSlot.Length < storage.SlotCount) Array.Resize(ref _indexOfSlot, Math.Max(16, storage.SlotCount * 2));

            BodyCount = 1;
            BodySlot[0] = -1;
            for (int k = 0; k < islands.ManifoldCount; k++)
            {
                ref ContactManifold m = ref manifolds[islands.Manifolds[k]];
                Index(m.BodyA);
                Index(m.BodyB);
            }
            for (int k = 0; k < islands.JointCount; k++)
            {
                ref JointData j = ref joints.Data[islands.Joints[k]];
                Index(j.BodyA);
                Index(j.BodyB);
            }
        }

        /// <summary>
        /// Sizes the per-step arrays for up to <paramref name="bodies"/> solver bodies (body
        /// slots below that), <paramref name="manifolds"/> contact manifolds and
        /// <paramref name="joints"/> joints, so steps within those counts allocate nothing.
        /// </summary>
        public void Reserve(int bodies, int manifolds, int joints)
        {
            int b = bodies + 1;
            if (_indexOfSlot.Length < b) Array.Resize(ref _indexOfSlot, b);
            if (Bodies.Length < b)
            {
                Array.Resize(ref Bodies, b);
                Array.Resize(ref BodySlot, b);
                Array.Resize(ref _startCenter, b);
                Array.Resize(ref _startRotation, b);
                Array.Resize(ref _colorMask, b);
            }
            if (_color.Length < manifolds + joints) _color = new int[manifolds + joints];
            if (Contacts.Length < manifolds) Contacts = new ContactConstraint[manifolds];
            if (Points.Length < 4 * manifolds) Points = new ContactConstraintPoint[4 * manifolds];
            if (JointOrder.Length < joints) JointOrder = new int[joints];
            if (_scalarContacts.Length < manifolds) _scalarContacts = new int[manifolds];
            _shock.Reserve(b, manifolds);
#if NET
            if (_rejected.Length < manifolds) _rejected = new int[manifolds];
            // Each colour's last group may be padded: at most one group per colour more.
            int width = ContactSolverWide.Width;
            int groups = (manifolds + width - 1) / width + Buckets;
            int lanes = groups * width;
            if (_wide.Length < groups)
            {
                _wide = new WideContact[groups];
                _wideImpact = new WideImpact[groups];
            }
            if (_wideManifold.Length < lanes) _wideManifold = new int[lanes];
            if (_wideBodies.Length < 2 * lanes) _wideBodies = new int[2 * lanes];
            if (_wideSlots.Length < 4 * lanes) _wideSlots = new int[4 * lanes];
            if (_wideSource.Length < lanes) _wideSource = new int[lanes];
#endif
        }

        /// <summary>The solver index of a body slot (0 for the fixed body and the world, -1).</summary>
        public int IndexOf(int slot) => slot < 0 ? 0 : _indexOfSlot[slot];

        int Index(int slot)
        {
            if (slot < 0) return 0;
            int k = _indexOfSlot[slot];
            if (k != 0) return k;
            BodyType type = _storage.Type[slot];
            if (type == BodyType.Static || !_storage.Awake[slot]) return 0;
            k = BodyCount++;
            if (k == Bodies.Length)
            {
                int n = k * 2;
                Array.Resize(ref Bodies, n);
                Array.Resize(ref BodySlot, n);
                Array.Resize(ref _startCenter, n);
                Array.Resize(ref _startRotation, n);
                Array.Resize(ref _colorMask, n);
            }
            BodySlot[k] = slot;
            _indexOfSlot[slot] = k;
            return k;
        }

        /// <summary>
        /// Copies the bodies' state into the solver bodies and builds every constraint of the
        /// step: colours them, then prepares them in colour order. With <paramref name="wide"/>
        /// the four-point manifolds go to the SIMD path, prepared lane-wise straight from the
        /// manifolds, unless <paramref name="keepRows"/> asks for every manifold's scalar rows
        /// (PGS's position passes read them): the wide groups are then loaded from those.
        /// </summary>
        public void Prepare(IslandBuilder islands, bool wide = false, bool keepRows = false)
        {
            BodyStorage s = _storage;
            Bodies[0] = new SolverBody { DeltaRotation = Quaternion.Identity };
            for (int k = 1; k < BodyCount; k++)
            {
                int i = BodySlot[k];
                bool dynamic = s.Type[i] == BodyType.Dynamic;
                ref SolverBody body = ref Bodies[k];
                body.LinearVelocity = s.LinearVelocity[i];
                body.AngularVelocity = s.AngularVelocity[i];
                body.InverseMass = dynamic ? s.InverseMass[i] : 0;
                body.InverseInertia = dynamic ? s.InverseInertiaWorld[i] : default;
                body.IsDynamic = dynamic ? 1 : 0;
                body.DeltaPosition = Vector3.Zero;
                body.DeltaRotation = Quaternion.Identity;
                _startCenter[k] = s.Center[i];
                _startRotation[k] = s.Rotation[i];
                _colorMask[k] = 0;
            }

            ref readonly WorldSettings set = ref _settings;
            float contactHertz = MathF.Min(set.ContactHertz, Softness.MaxStableHertz(_h));
            _contactSoftness = Softness.Make(contactHertz, set.ContactDampingRatio, _h);
            _fixedSoftness = Softness.Make(MathF.Min(2f * contactHertz, Softness.MaxStableHertz(_h)), set.ContactDampingRatio, _h);

            _jointParameters = new JointSolver.StepParameters
            {
                Joint = Softness.Make(MathF.Min(set.JointHertz, Softness.MaxStableHertz(_h)), set.JointDampingRatio, _h).WithMaxBias(set.MaxJointCorrectionSpeed),
                H = _h,
                InvH = _invH,
                // Joints are projected fully in each position pass (Box2D v2.x); a fraction, as
                // for contacts, converges far too slowly along chains with large mass ratios.
                Beta = 1f,
            };

            // Colour every constraint in a fixed order: contacts, then joints.
            int nm = islands.ManifoldCount, nj = islands.JointCount;
            if (_color.Length < nm + nj) _color = new int[Math.Max(16, 2 * (nm + nj))];
            Array.Clear(_contactCursor, 0, Buckets);
            Array.Clear(_jointCursor, 0, Buckets);
            Array.Clear(_pointCursor, 0, Buckets);
#if NET
            bool direct = wide && WideContacts && !keepRows && _settings.BlockSolver && Vector.IsHardwareAccelerated;
            if (direct) Array.Clear(_wideCursor, 0, Buckets);
#endif
            for (int k = 0; k < nm; k++)
            {
                ref ContactManifold m = ref _manifolds[islands.Manifolds[k]];
                if (m.PointCount > ContactManifold.MaxPoints) m.PointCount = ContactManifold.MaxPoints;
                int a = IndexOf(m.BodyA), b = IndexOf(m.BodyB);
                int c = ConstraintColoring.Assign(_colorMask, a, Bodies[a].IsDynamic != 0, b, Bodies[b].IsDynamic != 0);
#if NET
                if (direct && c < ConstraintColoring.MaxColors && ContactSolverWide.MayAccept(m))
                {
                    // A wide candidate: its colour plus Buckets marks it.
                    _color[k] = c + Buckets;
                    _wideCursor[c]++;
                    continue;
                }
#endif
                _color[k] = c;
                _contactCursor[c]++;
                _pointCursor[c] += m.PointCount;
            }
            for (int k = 0; k < nj; k++)
            {
                ref JointData j = ref _joints.Data[islands.Joints[k]];
                int a = IndexOf(j.BodyA), b = IndexOf(j.BodyB);
                int c = ConstraintColoring.Assign(_colorMask, a, Bodies[a].IsDynamic != 0, b, Bodies[b].IsDynamic != 0);
                _color[nm + k] = c;
                _jointCursor[c]++;
            }
            float warmContacts = set.WarmStarting ? _h / _previousDt : 0f;
            HasRestitution = false;
#if NET
            if (direct) PrepareWide(islands, warmContacts);
#endif
            // Prefix sums: bucket starts, then the counters become insertion cursors.
            int contacts = 0, joints = 0, points = 0;
            for (int c = 0; c < Buckets; c++)
            {
                _contactStart[c] = contacts;
                _jointStart[c] = joints;
                int nc = _contactCursor[c], njc = _jointCursor[c], np = _pointCursor[c];
                _contactCursor[c] = contacts;
                _jointCursor[c] = joints;
                _pointCursor[c] = points;
                contacts += nc;
                joints += njc;
                points += np;
            }
            _contactStart[Buckets] = contacts;
            _jointStart[Buckets] = joints;
            ContactCount = contacts;
            JointCount = joints;
            PointCount = points;
            if (Contacts.Length < contacts) Contacts = new ContactConstraint[Math.Max(16, contacts * 2)];
            if (Points.Length < points) Points = new ContactConstraintPoint[Math.Max(64, points * 2)];
            if (JointOrder.Length < joints) JointOrder = new int[Math.Max(16, joints * 2)];

            bool block = set.BlockSolver;
            for (int k = 0; k < nm; k++)
            {
                int c = _color[k];
                if (c >= Buckets) continue;
                PrepareScalar(islands.Manifolds[k], c, warmContacts, block);
            }
#if NET
            if (direct)
            {
                // The wide path's rejects, colour by colour, after that colour's other contacts.
                for (int c = 0; c < Buckets; c++)
                    for (int r = _rejectedStart[c]; r < _rejectedStart[c + 1]; r++)
                        PrepareScalar(_rejected[r], c, warmContacts, block);
                if (_scalarContacts.Length < contacts) _scalarContacts = new int[Math.Max(16, 2 * contacts)];
                for (int k = 0; k < contacts; k++) _scalarContacts[k] = k;
                Array.Copy(_contactStart, _scalarStart, Buckets + 1);
            }
            else
#endif
            SplitWide(wide && WideContacts);
            float warmJoints = set.WarmStarting ? 1f : 0f;
            for (int k = 0; k < nj; k++)
            {
                int slot = islands.Joints[k];
                int at = _jointCursor[_color[nm + k]]++;
                JointOrder[at] = slot;
                ref JointData j = ref _joints.Data[slot];
                j.SolverA = IndexOf(j.BodyA);
                j.SolverB = IndexOf(j.BodyB);
                JointSolver.Begin(ref j, _storage, _h, warmJoints);
                RunJoint(ref j, JointSolver.Pass.Prepare);
            }
        }

        void PrepareScalar(int mi, int c, float warmContacts, bool block)
        {
            ref ContactManifold m = ref _manifolds[mi];
            HasRestitution |= m.Restitution > 0;
            int at = _contactCursor[c]++;
            int firstPoint = _pointCursor[c];
            _pointCursor[c] += m.PointCount;
            ContactSolver.Prepare(ref Contacts[at], Points, firstPoint, ref m, mi, Bodies, IndexOf(m.BodyA), IndexOf(m.BodyB),
                _contactSoftness, _fixedSoftness, warmContacts, block);
        }

#if NET
        // The wide candidates (colour + Buckets in _color) into lanes, colour by colour, each
        // colour's last group padded; then prepared lane-wise. Rejected lanes are counted into
        // their colour's scalar contacts.
        void PrepareWide(IslandBuilder islands, float warmContacts)
        {
            int width = ContactSolverWide.Width;
            int groups = 0;
            for (int c = 0; c < Buckets; c++)
            {
                int count = _wideCursor[c];
                _wideStart[c] = groups;
                _wideCursor[c] = groups * width;
                groups += (count + width - 1) / width;
            }
            _wideStart[Buckets] = groups;
            _wideGroups = groups;
            int lanes = groups * width;
            int nm = islands.ManifoldCount;
            if (_wide.Length < groups)
            {
                _wide = new WideContact[2 * groups];
                _wideImpact = new WideImpact[2 * groups];
            }
            if (_wideManifold.Length < lanes)
            {
                _wideManifold = new int[2 * lanes];
                _wideBodies = new int[4 * lanes];
                _wideSlots = new int[8 * lanes];
            }
            if (_rejected.Length < nm) _rejected = new int[Math.Max(16, 2 * nm)];
            Array.Fill(_wideManifold, -1, 0, lanes);
            Array.Clear(_wideBodies, 0, 2 * lanes);
            for (int k = 0; k < nm; k++)
            {
                int c = _color[k] - Buckets;
                if (c < 0) continue;
                int lane = _wideCursor[c]++;
                int mi = islands.Manifolds[k];
                ref ContactManifold m = ref _manifolds[mi];
                _wideManifold[lane] = mi;
                _wideBodies[2 * lane] = IndexOf(m.BodyA);
                _wideBodies[2 * lane + 1] = IndexOf(m.BodyB);
            }
            int rejected = 0;
            for (int c = 0; c < Buckets; c++)
            {
                _rejectedStart[c] = rejected;
                HasRestitution |= ContactSolverWide.Prepare(_wide, _wideImpact, _wideStart[c], _wideStart[c + 1], _wideManifold, _wideBodies,
                    _wideSlots, _manifolds, Bodies, warmContacts, _rejected, ref rejected);
                for (int r = _rejectedStart[c]; r < rejected; r++)
                {
                    _contactCursor[c]++;
                    _pointCursor[c] += ContactManifold.MaxPoints;
                }
            }
            _rejectedStart[Buckets] = rejected;
        }
#endif

        // Sorts each colour's contacts into wide groups (those ContactSolverWide accepts, in
        // groups of Vector<float>.Count, the last one padded) and the scalar rest.
        void SplitWide(bool wide)
        {
            if (_scalarContacts.Length < ContactCount) _scalarContacts = new int[Math.Max(16, 2 * ContactCount)];
            int scalar = 0;
            _wideGroups = 0;
#if NET
            int width = ContactSolverWide.Width;
            int lanes = 0;
            if (wide && _wideSource.Length < ContactCount + Buckets * width)
            {
                int n = 2 * ContactCount + Buckets * width;
                _wideSource = new int[n];
            }
#else
            wide = false;
#endif
            for (int c = 0; c < Buckets; c++)
            {
                _scalarStart[c] = scalar;
                _wideStart[c] = _wideGroups;
                for (int k = _contactStart[c], end = _contactStart[c + 1]; k < end; k++)
                {
#if NET
                    if (wide && c < ConstraintColoring.MaxColors && ContactSolverWide.Accepts(Contacts[k]))
                    {
                        _wideSource[lanes++] = k;
                        continue;
                    }
#endif
                    _scalarContacts[scalar++] = k;
                }
#if NET
                // Close the colour's last group (padding lanes are -1).
                while (lanes % width != 0) _wideSource[lanes++] = -1;
                _wideGroups = lanes / width;
#endif
            }
            _scalarStart[Buckets] = scalar;
            _wideStart[Buckets] = _wideGroups;
#if NET
            if (_wideGroups == 0) return;
            if (_wide.Length < _wideGroups)
            {
                _wide = new WideContact[2 * _wideGroups];
                _wideImpact = new WideImpact[2 * _wideGroups];
                _wideManifold = new int[2 * _wideGroups * width];
                _wideBodies = new int[2 * 2 * _wideGroups * width];
                _wideSlots = new int[2 * 4 * _wideGroups * width];
            }
            for (int g = 0; g < _wideGroups; g++)
            {
                ReadOnlySpan<int> used = WideLanes(g);
                ContactSolverWide.Load(ref _wide[g], ref _wideImpact[g], _wideBodies, g * width, used, Contacts, Points, _manifolds, _wideSlots);
                for (int lane = 0; lane < width; lane++)
                    _wideManifold[g * width + lane] = lane < used.Length ? Contacts[used[lane]].Manifold : -1;
            }
#endif
        }

#if NET
        // The constraint indices of group g's used lanes.
        ReadOnlySpan<int> WideLanes(int g)
        {
            int width = ContactSolverWide.Width;
            var lanes = new ReadOnlySpan<int>(_wideSource, g * width, width);
            int used = 0;
            while (used < width && lanes[used] >= 0) used++;
            return lanes.Slice(0, used);
        }
#endif

        void RunJoint(ref JointData j, JointSolver.Pass pass)
        {
            SolverBody a = Bodies[j.SolverA];
            SolverBody b = Bodies[j.SolverB];
            JointSolver.Run(ref j, ref a, ref b, pass, _jointParameters);
            if (a.IsDynamic != 0) Bodies[j.SolverA] = a;
            if (b.IsDynamic != 0) Bodies[j.SolverB] = b;
        }

        // ---- passes ---------------------------------------------------------------------

        /// <summary>v += h (g + F/m), w += h I^-1 tau for the dynamic solver bodies (TGS substeps).</summary>
        public void IntegrateVelocities()
        {
            _bodyJob.Positions = false;
            if (Pool != null) Pool.For(_bodyJob, 1, BodyCount, 4 * MinChunk);
            else _bodyJob.Execute(1, BodyCount);
        }

        /// <summary>Levels the step's bodies and collects the contacts between levels for <see cref="Shock"/>.</summary>
        public void PrepareShock(IslandBuilder islands) =>
            _shock.Build(Bodies, BodyCount, _manifolds, islands.Manifolds, islands.ManifoldCount, _indexOfSlot, _settings.LinearSlop, _settings.ShockDepth, _dt);

        /// <summary>The shock-propagation sweep of the substep (see <see cref="ShockPropagation"/>).</summary>
        public void Shock()
        {
            Vector3 g = _settings.Gravity;
            float length = g.Length();
            _shock.Sweep(Bodies, _settings.ShockDepth, length > 0 ? -g / length : Vector3.Zero);
        }

        /// <summary>
        /// dp += v h and dq = exp(w h) dq for every moving solver body (TGS substeps); a dynamic
        /// body whose principal moments differ turns as a free body does
        /// (<see cref="Integrator.RotateFreeBody"/>), so that its angular momentum, not its
        /// angular velocity, is what carries over between constraint impulses (the gyroscopic
        /// terms).
        /// </summary>
        public void IntegratePositions()
        {
            _bodyJob.Positions = true;
            if (Pool != null) Pool.For(_bodyJob, 1, BodyCount, 4 * MinChunk);
            else _bodyJob.Execute(1, BodyCount);
        }

        /// <summary>Velocity or position integration of the solver bodies [start, end).</summary>
        sealed class BodyJob : IRangeJob
        {
            readonly SolverContext _c;
            public bool Positions;

            public BodyJob(SolverContext context) => _c = context;

            public void Execute(int start, int end)
            {
                SolverContext c = _c;
                SolverBody[] bodies = c.Bodies;
                BodyStorage s = c._storage;
                if (Positions)
                {
                    float h = c._h;
                    float speedCap = c._settings.MaxLinearSpeed;
                    for (int k = start; k < end; k++)
                    {
                        ref SolverBody body = ref bodies[k];
                        // The cap holds for what the constraints added too: a light body jointed
                        // to a heavy one in a contradictory pose was flung at 1e5 m/s (WorldFuzz).
                        if (body.IsDynamic != 0) Integrator.ClampSpeed(speedCap, s.Radius[c.BodySlot[k]], ref body.LinearVelocity, ref body.AngularVelocity);
                        body.DeltaPosition += h * body.LinearVelocity;
                        if (body.AngularVelocity == Vector3.Zero) continue;
                        int slot = c.BodySlot[k];
                        Vector3 ii = s.InverseInertiaPrincipal[slot];
                        if (body.IsDynamic == 0 || (ii.X == ii.Y && ii.Y == ii.Z))
                        {
                            body.DeltaRotation = Rotation.Integrate(body.DeltaRotation, body.AngularVelocity, h);
                            continue;
                        }
                        Quaternion start0 = c._startRotation[k];
                        Quaternion q = body.DeltaRotation * start0;
                        Integrator.RotateFreeBody(ref q, ref body.AngularVelocity, ii, s.InertiaFrame[slot], h);
                        body.DeltaRotation = q * Quaternion.Conjugate(start0);
                    }
                    return;
                }
                Vector3 g = c._settings.Gravity;
                float maxSpeed = c._settings.MaxLinearSpeed;
                for (int k = start; k < end; k++)
                {
                    ref SolverBody body = ref bodies[k];
                    if (body.IsDynamic == 0) continue;
                    Integrator.IntegrateVelocity(s, c.BodySlot[k], g, c._h, maxSpeed, ref body.LinearVelocity, ref body.AngularVelocity);
                }
            }
        }

        /// <summary>
        /// Applies the accumulated impulses of every constraint. The wide contacts also take their
        /// separations at the bodies' pose now, which the biased passes that follow read.
        /// </summary>
        public void WarmStart() => RunColors(ColorPass.WarmStart);

        /// <summary>
        /// One Gauss-Seidel pass over every constraint, colour by colour; biased (soft, pushing out)
        /// or not (relax). A biased pass takes the wide contacts' separations from the last
        /// <see cref="WarmStart"/>: the bodies must not have moved since.
        /// </summary>
        public void Solve(bool useBias) => RunColors(useBias ? ColorPass.Solve : ColorPass.Relax);

        /// <summary>Restitution's free approach speeds from the velocities now (TGS, each substep; see ContactSolver.RecordImpact).</summary>
        public void RefreshApproach() => RunColors(ColorPass.Approach);

        /// <summary>The restitution pass over every contact.</summary>
        public void ApplyRestitution() => RunColors(ColorPass.Restitution);

        /// <summary>One non-linear Gauss-Seidel position pass (PGS).</summary>
        public void SolvePositions() => RunColors(ColorPass.Position);

        // Colour by colour: the constraints of one colour touch disjoint dynamic bodies, so with
        // a worker pool they are split between threads; the overflow batch runs on the caller.
        void RunColors(ColorPass pass)
        {
            ColorJob job = _colorJob;
            job.Pass = pass;
            for (int c = 0; c < Buckets; c++)
            {
                job.WideStart = _wideStart[c];
                job.WideCount = _wideStart[c + 1] - _wideStart[c];
                job.ContactStart = _scalarStart[c];
                job.ContactCount = _scalarStart[c + 1] - _scalarStart[c];
                job.JointStart = _jointStart[c];
                int count = job.WideCount + job.ContactCount + (_jointStart[c + 1] - _jointStart[c]);
                if (count == 0) continue;
                // A wide group is a vector's worth of manifolds: split those finer.
                int minChunk = 2 * job.WideCount > count ? MinChunk / 8 : MinChunk;
                if (Pool != null && c < ConstraintColoring.MaxColors) Pool.For(job, 0, count, minChunk);
                else job.Execute(0, count);
            }
        }

        /// <summary>Constraints (or bodies) a thread takes at a time: below this, splitting costs more than it saves.</summary>
        const int MinChunk = 32;

        enum ColorPass : byte { WarmStart, Solve, Relax, Restitution, Approach, Position }

        /// <summary>One pass over the items [start, end) of a colour: its contacts, then its joints.</summary>
        sealed class ColorJob : IRangeJob
        {
            readonly SolverContext _c;
            public ColorPass Pass;
            public int WideStart, WideCount, ContactStart, ContactCount, JointStart;

            public ColorJob(SolverContext context) => _c = context;

            public void Execute(int start, int end)
            {
                SolverContext c = _c;
#if NET
                int wideEnd = Math.Min(end, WideCount);
                if (start < wideEnd)
                {
                    int first = WideStart + start, last = WideStart + wideEnd;
                    switch (Pass)
                    {
                        case ColorPass.WarmStart: ContactSolverWide.WarmStart(c._wide, first, last, c.Bodies, c._wideBodies); break;
                        case ColorPass.Solve: ContactSolverWide.Solve(c._wide, c._wideImpact, first, last, c.Bodies, c._wideBodies, c._contactSoftness, c._fixedSoftness, c._invH, c._settings.MaxContactPushSpeed, true); break;
                        case ColorPass.Relax: ContactSolverWide.Solve(c._wide, c._wideImpact, first, last, c.Bodies, c._wideBodies, c._contactSoftness, c._fixedSoftness, c._invH, c._settings.MaxContactPushSpeed, false); break;
                        case ColorPass.Restitution: ContactSolverWide.ApplyRestitution(c._wide, c._wideImpact, first, last, c.Bodies, c._wideBodies, c._settings.RestitutionThreshold); break;
                        case ColorPass.Approach: ContactSolverWide.RefreshApproach(c._wide, c._wideImpact, first, last, c.Bodies, c._wideBodies); break;
                        default:
                            // The position pass needs only geometry, which the scalar constraints keep.
                            for (int g = first; g < last; g++)
                            {
                                ReadOnlySpan<int> lanes = c.WideLanes(g);
                                for (int lane = 0; lane < lanes.Length; lane++)
                                    ContactPositionSolver.Solve(ref c.Contacts[lanes[lane]], c.Points, c.Bodies, c._settings.LinearSlop, c._settings.MaxContactPushSpeed * c._dt);
                            }
                            break;
                    }
                }
#endif
                start = Math.Max(start, WideCount) - WideCount;
                end -= WideCount;
                if (end <= 0) return;
                int contactEnd = Math.Min(end, ContactCount);
                for (int i = start; i < contactEnd; i++)
                {
                    ref ContactConstraint k = ref c.Contacts[c._scalarContacts[ContactStart + i]];
                    switch (Pass)
                    {
                        case ColorPass.WarmStart: ContactSolver.WarmStart(ref k, c.Points, c.Bodies); break;
                        case ColorPass.Solve: ContactSolver.Solve(ref k, c.Points, c.Bodies, c._invH, c._settings.MaxContactPushSpeed, true); break;
                        case ColorPass.Relax: ContactSolver.Solve(ref k, c.Points, c.Bodies, c._invH, c._settings.MaxContactPushSpeed, false); break;
                        case ColorPass.Restitution: ContactSolver.ApplyRestitution(ref k, c.Points, c.Bodies, c._settings.RestitutionThreshold); break;
                        case ColorPass.Approach: ContactSolver.RefreshApproach(ref k, c.Points, c.Bodies); break;
                        default: ContactPositionSolver.Solve(ref k, c.Points, c.Bodies, c._settings.LinearSlop, c._settings.MaxContactPushSpeed * c._dt); break;
                    }
                }
                if (Pass == ColorPass.Restitution || Pass == ColorPass.Approach) return;
                JointSolver.Pass jointPass = Pass == ColorPass.WarmStart ? JointSolver.Pass.WarmStart
                    : Pass == ColorPass.Solve ? JointSolver.Pass.Solve
                    : Pass == ColorPass.Relax ? JointSolver.Pass.Relax
                    : JointSolver.Pass.Position;
                for (int i = Math.Max(start, ContactCount); i < end; i++)
                    c.RunJoint(ref c._joints.Data[c.JointOrder[JointStart + i - ContactCount]], jointPass);
            }
        }

        /// <summary>Copies the solver bodies' velocities back to the dynamic bodies.</summary>
        public void StoreVelocities()
        {
            BodyStorage s = _storage;
            for (int k = 1; k < BodyCount; k++)
            {
                ref SolverBody body = ref Bodies[k];
                if (body.IsDynamic == 0) continue;
                int i = BodySlot[k];
                Vector3 v = body.LinearVelocity, w = body.AngularVelocity;
                // The relax and restitution passes run after the capped position integration:
                // cap what they leave too, so no body ends a step above the documented speeds
                // (a 0.3 kg body between conflicting joints reported 4000 m/s).
                Integrator.ClampSpeed(_settings.MaxLinearSpeed, s.Radius[i], ref v, ref w);
                s.LinearVelocity[i] = v;
                s.AngularVelocity[i] = w;
            }
        }

        /// <summary>Copies the dynamic bodies' velocities into the solver bodies (after the integrator turned them, PGS).</summary>
        public void LoadVelocities()
        {
            BodyStorage s = _storage;
            for (int k = 1; k < BodyCount; k++)
            {
                ref SolverBody body = ref Bodies[k];
                if (body.IsDynamic == 0) continue;
                int i = BodySlot[k];
                body.LinearVelocity = s.LinearVelocity[i];
                body.AngularVelocity = s.AngularVelocity[i];
            }
        }

        /// <summary>Sets each solver body's deltas from where the integrator moved its body (PGS, before the position passes).</summary>
        public void LoadDeltas()
        {
            BodyStorage s = _storage;
            for (int k = 1; k < BodyCount; k++)
            {
                int i = BodySlot[k];
                ref SolverBody body = ref Bodies[k];
                body.DeltaPosition = s.Center[i] - _startCenter[k];
                body.DeltaRotation = Quaternion.Normalize(s.Rotation[i] * Quaternion.Conjugate(_startRotation[k]));
            }
        }

        /// <summary>Moves every solver body to its start pose plus its deltas; refreshes origin and world inertia.</summary>
        public void StorePositions()
        {
            BodyStorage s = _storage;
            for (int k = 1; k < BodyCount; k++)
            {
                int i = BodySlot[k];
                ref SolverBody body = ref Bodies[k];
                s.Center[i] = _startCenter[k] + body.DeltaPosition;
                s.Rotation[i] = Quaternion.Normalize(body.DeltaRotation * _startRotation[k]);
                s.SyncOriginFromCenter(i);
                s.UpdateWorldInertia(i);
            }
        }

        /// <summary>
        /// Adds each contact point's current normal impulse to what the step has applied so
        /// far. Called at the end of every TGS substep: the impulse of a substep is re-applied
        /// (warm start) and corrected within the substep, so its end value is what that substep
        /// applied. PGS never calls it; its single velocity solve applies the stored impulse.
        /// </summary>
        public void AccumulateApplied()
        {
            for (int k = 0; k < _scalarStart[Buckets]; k++)
            {
                ref ContactConstraint c = ref Contacts[_scalarContacts[k]];
                for (int p = c.FirstPoint, end = c.FirstPoint + c.PointCount; p < end; p++)
                {
                    ref ContactConstraintPoint point = ref Points[p];
                    point.Applied += point.Normal.Impulse;
                    point.LastSubstep = point.Normal.Impulse;
                }
            }
#if NET
            for (int g = 0; g < _wideGroups; g++) ContactSolverWide.Accumulate(_wide[g], ref _wideImpact[g]);
#endif
        }

        /// <summary>
        /// Ends the step: impulses back into the manifolds (per step: times the substep count),
        /// joint reports (force, torque, stress, error). Returns the largest joint error, m.
        /// </summary>
        public float End()
        {
            float scale = _dt / _h;
            for (int k = 0; k < _scalarStart[Buckets]; k++)
            {
                ref ContactConstraint c = ref Contacts[_scalarContacts[k]];
                ContactSolver.Store(c, Points, ref _manifolds[c.Manifold], scale);
            }
#if NET
            int width = ContactSolverWide.Width;
            for (int g = 0; g < _wideGroups; g++)
                ContactSolverWide.Store(_wide[g], _wideImpact[g], _wideSlots, _wideManifold, g * width, _manifolds, scale);
#endif
            float maxError = 0;
            for (int k = 0; k < JointCount; k++)
            {
                ref JointData j = ref _joints.Data[JointOrder[k]];
                RunJoint(ref j, JointSolver.Pass.Report);
                maxError = MathF.Max(maxError, j.Error);
            }
            for (int k = 1; k < BodyCount; k++) _indexOfSlot[BodySlot[k]] = 0;
            _previousDt = _dt;
            return maxError;
        }
    }
}
