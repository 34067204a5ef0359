using System;
using System.Numerics;
using Fulcrum.Collision;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// The solver's working set for one step: the solver bodies (a compact copy of the bodies
    /// that take part in constraints), the contact constraints and their points, the step's
    /// joints, all ordered by colour (<see cref="ConstraintColoring"/>), and the passes that
    /// <see cref="PgsSolver"/> and <see cref="TgsSolver"/> compose: integrate, warm start,
    /// solve, relax, restitution, position correction, write-back. Every array is kept from
    /// step to step and grows only when a step needs more: a steady step allocates nothing.
    /// This file holds the state and the copies of the bodies in and out; the colouring and
    /// preparation of the constraints are in SolverContext.Batches.cs, the passes in
    /// SolverContext.Passes.cs.
    /// </summary>
    internal sealed partial class SolverContext
    {
        const int Buckets = ConstraintColoring.MaxColors + 1;

        // Solver bodies; index 0 is the fixed body.
        public SolverBody[] Bodies = new SolverBody[16];
        public int BodyCount;
        /// <summary>Body slot of each solver body (index 0: -1).</summary>
        public int[] BodySlot = new int[16];
        Vector3[] _startCenter = new Vector3[16];
        Quaternion[] _startRotation = new Quaternion[16];
        // Per dynamic solver body: its substep velocity update (filled by Prepare).
        SubstepKick[] _kick = new SubstepKick[16];
        int[] _indexOfSlot = Array.Empty<int>();
        ulong[] _colorMask = new ulong[16];
        bool[] _runaway = new bool[16];

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

        /// <summary>The step's length, s.</summary>
        public float StepDt => _dt;
        float _previousDt;
        ContactStep _contactStep;
        JointSolver.StepParameters _jointParameters;
        readonly ColorJob _colorJob;
        readonly BodyJob _bodyJob;
        readonly GroupJob _groupJob;
        readonly ShockPropagation _shock = new ShockPropagation();

        /// <summary>The shock-propagation sweep (for tests).</summary>
        internal ShockPropagation ShockForTests => _shock;
        // Per contact constraint, for PGS's position passes: 0, or the body held still (1 A, 2 B).
        byte[] _held = new byte[16];
        readonly JointTreeSolver _trees = new JointTreeSolver();

        // Contacts of each colour not taken by the wide path, by index into Contacts.
        int[] _scalarContacts = new int[16];
        readonly int[] _scalarStart = new int[Buckets + 1];
        // Wide groups (net10): per colour a range of groups of Vector<float>.Count manifolds.
        readonly int[] _wideStart = new int[Buckets + 1];
        int _wideGroups;

        /// <summary>Wide groups of the last step (for tests and profiling).</summary>
        public int WideGroupCount => _wideGroups;

        /// <summary>Whether the wide (SIMD) contact path may take four-point manifolds (net10 with SIMD hardware).</summary>
        public bool WideContacts = true;

        /// <summary>Threads for the colour batches; null runs everything on the caller's thread.</summary>
        public IParallelScheduler? Pool;

        /// <summary>Keeps the velocity solve from creating kinetic energy (see <see cref="EnergyGuard"/>).</summary>
        public readonly EnergyGuard Guard = new EnergyGuard();

        /// <summary>Groups the prepared bodies into islands for <see cref="Guard"/>.</summary>
        public void BuildGuard(IslandBuilder islands)
        {
            Guard.Build(this, islands, _manifolds, _joints);
        }

        /// <summary>Closes the <see cref="Guard"/>'s window: scales back what created energy.</summary>
        public void EndGuard(IslandBuilder islands) => Guard.End(this, islands, _joints);

        public SolverContext()
        {
            _colorJob = new ColorJob(this);
            _bodyJob = new BodyJob(this);
            _groupJob = new GroupJob(this);
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
                Array.Resize(ref _kick, b);
                Array.Resize(ref _colorMask, b);
                Array.Resize(ref _runaway, b);
            }
            if (_color.Length < manifolds + joints) _color = new int[manifolds + joints];
            if (Contacts.Length < manifolds) Contacts = new ContactConstraint[manifolds];
            if (Points.Length < 4 * manifolds) Points = new ContactConstraintPoint[4 * manifolds];
            if (JointOrder.Length < joints) JointOrder = new int[joints];
            if (_scalarContacts.Length < manifolds) _scalarContacts = new int[manifolds];
            _shock.Reserve(b, manifolds);
            if (_held.Length < manifolds) _held = new byte[manifolds];
            Guard.Reserve(b);
            ReserveWide(manifolds);
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
                Array.Resize(ref _kick, n);
                Array.Resize(ref _colorMask, n);
            }
            BodySlot[k] = slot;
            _indexOfSlot[slot] = k;
            return k;
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

        /// <summary>
        /// Moves every solver body to its start pose plus its deltas; refreshes origin and world
        /// inertia. With <paramref name="turnVelocities"/> (after PGS's position passes) each
        /// dynamic body's angular velocity turns with the rotation those passes added, so the
        /// body keeps its spin in its own frame: a position correction may not change the
        /// rotational kinetic energy (with the world angular velocity held while the world
        /// inertia turned, a thin body re-oriented by a joint correction gained energy every
        /// step).
        /// </summary>
        public void StorePositions(bool turnVelocities = false)
        {
            BodyStorage s = _storage;
            for (int k = 1; k < BodyCount; k++)
            {
                int i = BodySlot[k];
                ref SolverBody body = ref Bodies[k];
                s.Center[i] = _startCenter[k] + body.DeltaPosition;
                Quaternion rotation = Quaternion.Normalize(body.DeltaRotation * _startRotation[k]);
                if (turnVelocities && body.IsDynamic != 0)
                {
                    Quaternion turn = rotation * Quaternion.Conjugate(s.Rotation[i]);
                    s.AngularVelocity[i] = Vector3.Transform(s.AngularVelocity[i], turn);
                    // Turned about a free axis, the spin stays on the free axes but for rounding.
                    if (body.IsDynamic > 1) s.AngularVelocity[i] = AxisLockMath.MaskAngular(s.AngularVelocity[i], body.Locks);
                }
                s.Rotation[i] = rotation;
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
            AccumulateWide();
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
            StoreWide(scale);
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
