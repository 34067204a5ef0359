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

        /// <summary>The (sub)step of the current solve, s.</summary>
        public float SubstepDt => _h;

        /// <summary>The settings of the current step.</summary>
        public ref readonly WorldSettings Settings => ref _settings;

        /// <summary>The body storage of the current step.</summary>
        public BodyStorage Storage => _storage;

        /// <summary>True when the step has any constraint to solve.</summary>
        public bool HasWork => ContactCount > 0 || JointCount > 0;

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
        /// step: colours them, then prepares them in colour order.
        /// </summary>
        public void Prepare(IslandBuilder islands)
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
                Joint = Softness.Make(MathF.Min(set.JointHertz, Softness.MaxStableHertz(_h)), set.JointDampingRatio, _h),
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
            for (int k = 0; k < nm; k++)
            {
                ref ContactManifold m = ref _manifolds[islands.Manifolds[k]];
                int a = IndexOf(m.BodyA), b = IndexOf(m.BodyB);
                int c = ConstraintColoring.Assign(_colorMask, a, Bodies[a].IsDynamic != 0, b, Bodies[b].IsDynamic != 0);
                _color[k] = c;
                _contactCursor[c]++;
                _pointCursor[c] += Math.Min(m.PointCount, ContactManifold.MaxPoints);
            }
            for (int k = 0; k < nj; k++)
            {
                ref JointData j = ref _joints.Data[islands.Joints[k]];
                int a = IndexOf(j.BodyA), b = IndexOf(j.BodyB);
                int c = ConstraintColoring.Assign(_colorMask, a, Bodies[a].IsDynamic != 0, b, Bodies[b].IsDynamic != 0);
                _color[nm + k] = c;
                _jointCursor[c]++;
            }
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

            float warmContacts = set.WarmStarting ? _h / _previousDt : 0f;
            bool block = set.BlockSolver;
            for (int k = 0; k < nm; k++)
            {
                int mi = islands.Manifolds[k];
                ref ContactManifold m = ref _manifolds[mi];
                if (m.PointCount > ContactManifold.MaxPoints) m.PointCount = ContactManifold.MaxPoints;
                int c = _color[k];
                int at = _contactCursor[c]++;
                int firstPoint = _pointCursor[c];
                _pointCursor[c] += m.PointCount;
                ContactSolver.Prepare(ref Contacts[at], Points, firstPoint, ref m, mi, Bodies, IndexOf(m.BodyA), IndexOf(m.BodyB),
                    _contactSoftness, _fixedSoftness, warmContacts, block);
            }
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
            BodyStorage s = _storage;
            Vector3 g = _settings.Gravity;
            float maxSpeed = _settings.MaxLinearSpeed;
            for (int k = 1; k < BodyCount; k++)
            {
                ref SolverBody body = ref Bodies[k];
                if (body.IsDynamic == 0) continue;
                Integrator.IntegrateVelocity(s, BodySlot[k], g, _h, maxSpeed, ref body.LinearVelocity, ref body.AngularVelocity);
            }
        }

        /// <summary>dp += v h and dq = exp(w h) dq for every moving solver body (TGS substeps).</summary>
        public void IntegratePositions()
        {
            float h = _h;
            for (int k = 1; k < BodyCount; k++)
            {
                ref SolverBody body = ref Bodies[k];
                body.DeltaPosition += h * body.LinearVelocity;
                if (body.AngularVelocity != Vector3.Zero)
                    body.DeltaRotation = Rotation.Integrate(body.DeltaRotation, body.AngularVelocity, h);
            }
        }

        /// <summary>Applies the accumulated impulses of every constraint.</summary>
        public void WarmStart()
        {
            for (int c = 0; c < Buckets; c++)
            {
                for (int k = _contactStart[c], end = _contactStart[c + 1]; k < end; k++)
                    ContactSolver.WarmStart(ref Contacts[k], Points, Bodies);
                for (int k = _jointStart[c], end = _jointStart[c + 1]; k < end; k++)
                    RunJoint(ref _joints.Data[JointOrder[k]], JointSolver.Pass.WarmStart);
            }
        }

        /// <summary>One Gauss-Seidel pass over every constraint, colour by colour; biased (soft, pushing out) or not (relax).</summary>
        public void Solve(bool useBias)
        {
            float invH = _invH, maxPush = _settings.MaxContactPushSpeed;
            JointSolver.Pass pass = useBias ? JointSolver.Pass.Solve : JointSolver.Pass.Relax;
            for (int c = 0; c < Buckets; c++)
            {
                for (int k = _contactStart[c], end = _contactStart[c + 1]; k < end; k++)
                    ContactSolver.Solve(ref Contacts[k], Points, Bodies, invH, maxPush, useBias);
                for (int k = _jointStart[c], end = _jointStart[c + 1]; k < end; k++)
                    RunJoint(ref _joints.Data[JointOrder[k]], pass);
            }
        }

        /// <summary>The restitution pass over every contact.</summary>
        public void ApplyRestitution()
        {
            float threshold = _settings.RestitutionThreshold;
            for (int k = 0; k < ContactCount; k++)
                ContactSolver.ApplyRestitution(ref Contacts[k], Points, Bodies, threshold);
        }

        /// <summary>One non-linear Gauss-Seidel position pass (PGS); returns the deepest contact overlap seen.</summary>
        public float SolvePositions()
        {
            float slop = _settings.LinearSlop, maxCorrection = _settings.MaxContactPushSpeed * _dt;
            float deepest = 0;
            for (int c = 0; c < Buckets; c++)
            {
                for (int k = _contactStart[c], end = _contactStart[c + 1]; k < end; k++)
                    deepest = MathF.Max(deepest, ContactPositionSolver.Solve(ref Contacts[k], Points, Bodies, slop, maxCorrection));
                for (int k = _jointStart[c], end = _jointStart[c + 1]; k < end; k++)
                    RunJoint(ref _joints.Data[JointOrder[k]], JointSolver.Pass.Position);
            }
            return deepest;
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
                s.LinearVelocity[i] = body.LinearVelocity;
                s.AngularVelocity[i] = body.AngularVelocity;
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
        /// Ends the step: impulses back into the manifolds (per step: times the substep count),
        /// joint reports (force, torque, stress, error). Returns the largest joint error, m.
        /// </summary>
        public float End()
        {
            float scale = _dt / _h;
            for (int k = 0; k < ContactCount; k++)
            {
                ref ContactConstraint c = ref Contacts[k];
                ContactSolver.Store(c, Points, ref _manifolds[c.Manifold], scale);
            }
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
