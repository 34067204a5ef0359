using System;
using System.Numerics;
using Fulcrum.Dynamics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The rigid bodies a soft body touches during the soft-body stage, moved through the same
    /// substeps as the soft body so that both sides of every contact and attachment see each
    /// other in every iteration (one coupled solve, as in Mueller et al. 2020, "Detailed Rigid
    /// Body Simulation with Extended Position Based Dynamics", where rigid bodies and particles
    /// share the substep loop).
    /// <para>
    /// A dynamic body is put back at its pose and velocity from the start of the step and
    /// integrated again substep by substep: v += a h, x += v h, with a = (v1 - v0) / dt the
    /// acceleration the rigid solve gave it (gravity, damping, rigid contacts and joints: the
    /// forces the soft body does not see are kept, applied at the substep rate), plus the
    /// solve's position correction (its end pose minus where its own integrator would have
    /// taken the body with that acceleration alone), spread evenly over the substeps. XPBD corrections pushed onto it (a position
    /// impulse P at a point) move it by P/m and I^-1 (r x P) and change its velocity by the same
    /// over h, exactly the momentum the vertex loses, and the next substep integrates on from
    /// there. Before, the body was walked along the rigid solve's end-of-step path (which had
    /// fallen a whole step under gravity without the soft body's support) and pushed back
    /// afterwards: an explicit, staggered coupling that rocked a heavy plate on a soft cube
    /// more every cycle until it slid off.
    /// </para>
    /// <para>
    /// A kinematic body follows its prescribed motion: walked from its start pose to its end
    /// pose (centre linearly, rotation by slerp). Writes body pose, velocity and world inertia
    /// in <see cref="BodyStorage"/>.
    /// </para>
    /// </summary>
    internal sealed class RigidCoupling
    {
        BodyStorage _bodies = null!;
        int[] _entryOfSlot = Array.Empty<int>();
        int[] _slot = Array.Empty<int>();
        Vector3[] _startCenter = Array.Empty<Vector3>();
        Quaternion[] _startRotation = Array.Empty<Quaternion>();
        Vector3[] _endCenter = Array.Empty<Vector3>();
        Quaternion[] _endRotation = Array.Empty<Quaternion>();
        // The body origin the rigid solve left (restored exactly, not recomputed from the centre).
        Vector3[] _endOrigin = Array.Empty<Vector3>();
        // Dynamic bodies: the rigid solve's acceleration over the step, and its position
        // correction per substep (linear, and as a rotation vector).
        Vector3[] _acceleration = Array.Empty<Vector3>();
        Vector3[] _angularAcceleration = Array.Empty<Vector3>();
        Vector3[] _correction = Array.Empty<Vector3>();
        Vector3[] _angularCorrection = Array.Empty<Vector3>();
        // Dynamic bodies: the velocity the rigid solve left them with (Restore).
        Vector3[] _endLinear = Array.Empty<Vector3>();
        Vector3[] _endAngular = Array.Empty<Vector3>();
        // Per tracked entry: how many soft bodies hold vertices attached to it this step, and
        // the last one counted (Carry).
        int[] _carriedBy = Array.Empty<int>();
        SoftBody?[] _lastCarrier = Array.Empty<SoftBody?>();
        // The soft bodies with vertices attached to a tracked dynamic body this step.
        SoftBody[] _carriers = Array.Empty<SoftBody>();
        int _carrierCount;
        int _count;
        float _dt;
        World _world = null!;

        /// <summary>Forgets last step's bodies; the coming step is <paramref name="dt"/> long.</summary>
        public void Begin(World world, float dt)
        {
            _world = world;
            BodyStorage bodies = world.Bodies;
            _bodies = bodies;
            _dt = dt;
            if (_entryOfSlot.Length < bodies.SlotCount)
            {
                int old = _entryOfSlot.Length;
                Array.Resize(ref _entryOfSlot, Math.Max(bodies.SlotCount, 2 * old));
                for (int i = old; i < _entryOfSlot.Length; i++) _entryOfSlot[i] = -1;
            }
            for (int k = 0; k < _count; k++) _entryOfSlot[_slot[k]] = -1;
            _count = 0;
            Array.Clear(_carriers, 0, _carrierCount);
            _carrierCount = 0;
        }

        /// <summary>Starts walking a moving body through the substeps (static bodies need nothing).</summary>
        public void Track(int slot)
        {
            if (_bodies.Type[slot] == BodyType.Static || _entryOfSlot[slot] >= 0) return;
            if (_count == _slot.Length) Grow(Math.Max(8, 2 * _count));
            int e = _count++;
            _entryOfSlot[slot] = e;
            _slot[e] = slot;
            _carriedBy[e] = 0;
            _lastCarrier[e] = null;
            BodyStorage b = _bodies;
            _startRotation[e] = b.PreviousRotation[slot];
            _startCenter[e] = b.PreviousPosition[slot] + Vector3.Transform(b.LocalCenter[slot], b.PreviousRotation[slot]);
            _endCenter[e] = b.Center[slot];
            _endRotation[e] = b.Rotation[slot];
            _endOrigin[e] = b.Position[slot];
            if (b.Type[slot] != BodyType.Dynamic) return;

            // Back to the start of the step; BeginSubstep integrates it again.
            Vector3 v0 = b.StartLinearVelocity[slot], w0 = b.StartAngularVelocity[slot];
            Vector3 v1 = b.LinearVelocity[slot], w1 = b.AngularVelocity[slot];
            _endLinear[e] = v1;
            _endAngular[e] = w1;
            float invDt = 1f / _dt;
            _acceleration[e] = (v1 - v0) * invDt;
            _angularAcceleration[e] = (w1 - w0) * invDt;
            // Where the rigid solver's own integrator (n substeps of v += a h, x += v h) takes the
            // body with that acceleration and no constraint: what it did beyond that is the
            // position correction of its contacts and joints (zero for a body in free flight).
            int n = _world.IntegratorSubsteps(slot);
            float hr = _dt / n;
            Vector3 center = _startCenter[e], v = v0, w = w0;
            Quaternion rotation = _startRotation[e];
            for (int k = 0; k < n; k++)
            {
                v += _acceleration[e] * hr;
                w += _angularAcceleration[e] * hr;
                center += v * hr;
                rotation = Rotation.Integrate(rotation, w, hr);
            }
            _correction[e] = _endCenter[e] - center;
            _angularCorrection[e] = Rotation.ToRotationVector(_endRotation[e] * Quaternion.Conjugate(rotation));
            b.Center[slot] = _startCenter[e];
            b.Rotation[slot] = _startRotation[e];
            b.LinearVelocity[slot] = v0;
            b.AngularVelocity[slot] = w0;
            b.SyncOriginFromCenter(slot);
            b.UpdateWorldInertia(slot);
        }

        /// <summary>
        /// Notes that <paramref name="body"/> holds vertices attached to the tracked dynamic body
        /// in <paramref name="slot"/> this step (after <see cref="Track"/>; see <see cref="Shared"/>).
        /// </summary>
        public void Carry(int slot, SoftBody body)
        {
            int e = _entryOfSlot[slot];
            if (e < 0 || _lastCarrier[e] == body) return;
            _lastCarrier[e] = body;
            _carriedBy[e]++;
            for (int c = 0; c < _carrierCount; c++)
                if (_carriers[c] == body) return;
            if (_carrierCount == _carriers.Length) Array.Resize(ref _carriers, Math.Max(4, 2 * _carrierCount));
            _carriers[_carrierCount++] = body;
        }

        /// <summary>Whether more than one soft body holds vertices attached to the body in <paramref name="slot"/> this step.</summary>
        public bool Shared(int slot)
        {
            int e = _entryOfSlot[slot];
            return e >= 0 && _carriedBy[e] > 1;
        }

        /// <summary>The soft bodies with vertices attached to a tracked dynamic body this step (<see cref="Carrier"/> 0 .. this - 1).</summary>
        public int CarrierCount => _carrierCount;

        /// <summary>Soft body <paramref name="c"/> of those with vertices attached to a tracked dynamic body this step.</summary>
        public SoftBody Carrier(int c) => _carriers[c];

        /// <summary>
        /// Puts every tracked dynamic body back where the rigid solve left it, pose and velocity:
        /// what the soft bodies did to it in this step is undone. For a step in which a soft body
        /// diverged (it is put back at its start, at rest): a 12 kg plate pinned to a soft sphere
        /// that blew up was left with the 154 m/s the failing step had pushed onto it, went
        /// through the ground and fell on (soft fuzz seed 42). A kinematic body goes back to the
        /// end of its path (the substeps had moved it along it).
        /// </summary>
        public void Restore()
        {
            BodyStorage b = _bodies;
            for (int e = 0; e < _count; e++)
            {
                int slot = _slot[e];
                if (b.Type[slot] == BodyType.Static) continue;
                b.Center[slot] = _endCenter[e];
                b.Rotation[slot] = _endRotation[e];
                b.Position[slot] = _endOrigin[e];
                b.UpdateWorldInertia(slot);
                if (b.Type[slot] != BodyType.Dynamic) continue;
                b.LinearVelocity[slot] = _endLinear[e];
                b.AngularVelocity[slot] = _endAngular[e];
            }
        }

        /// <summary>
        /// Sets the substeps of this step (known once every soft body has gathered what it may
        /// touch): the rigid solve's position corrections are spread over them.
        /// </summary>
        public void SetSubsteps(int substeps)
        {
            float invN = 1f / substeps;
            for (int e = 0; e < _count; e++)
            {
                if (_bodies.Type[_slot[e]] != BodyType.Dynamic) continue;
                _correction[e] *= invN;
                _angularCorrection[e] *= invN;
            }
        }

        /// <summary>
        /// Advances every tracked body to fraction <paramref name="t"/> of the step: a dynamic body
        /// by one substep of <paramref name="h"/> (velocity, then position, from where the soft
        /// bodies left it), a kinematic one along its prescribed path.
        /// </summary>
        public void BeginSubstep(float t, float h)
        {
            BodyStorage b = _bodies;
            for (int e = 0; e < _count; e++)
            {
                int slot = _slot[e];
                if (b.Type[slot] == BodyType.Dynamic)
                {
                    b.LinearVelocity[slot] += _acceleration[e] * h;
                    b.AngularVelocity[slot] += _angularAcceleration[e] * h;
                    b.Center[slot] += b.LinearVelocity[slot] * h + _correction[e];
                    b.Rotation[slot] = Quaternion.Normalize(Rotation.FromRotationVector(_angularCorrection[e])
                        * Rotation.Integrate(b.Rotation[slot], b.AngularVelocity[slot], h));
                }
                else if (t >= 1f)
                {
                    // The last substep ends exactly where the rigid solve put the body (the
                    // interpolation at t = 1 is a rounding away from it).
                    b.Center[slot] = _endCenter[e];
                    b.Rotation[slot] = _endRotation[e];
                    b.Position[slot] = _endOrigin[e];
                    b.UpdateWorldInertia(slot);
                    continue;
                }
                else
                {
                    b.Center[slot] = Vector3.Lerp(_startCenter[e], _endCenter[e], t);
                    b.Rotation[slot] = Quaternion.Normalize(Quaternion.Slerp(_startRotation[e], _endRotation[e], t));
                }
                b.SyncOriginFromCenter(slot);
                b.UpdateWorldInertia(slot);
            }
        }

        /// <summary>
        /// Whether the body in <paramref name="slot"/> can be moved by a soft body: dynamic and not
        /// locked on all six axes (<see cref="AxisLocks.All"/>). A body locked on all of them is met
        /// as a static one is (as attachments already took it): a Newton body's step met it as a
        /// dynamic body of zero inverse mass, whose share of the step was infinite, the step was
        /// skipped, and a Newton cube slid down such a ramp as on ice.
        /// </summary>
        public static bool Movable(BodyStorage b, int slot) =>
            b.Type[slot] == BodyType.Dynamic && (b.Locks[slot] & AxisLocks.All) != AxisLocks.All;

        /// <summary>
        /// The inverse mass a dynamic body shows along <paramref name="direction"/> (unit) at
        /// <paramref name="point"/>: 1/m + (r x n) . I^-1 (r x n); 0 for static and kinematic bodies.
        /// </summary>
        public float InverseMassAt(int slot, Vector3 point, Vector3 direction)
        {
            BodyStorage b = _bodies;
            if (b.Type[slot] != BodyType.Dynamic) return 0f;
            Vector3 rn = Vector3.Cross(point - b.Center[slot], direction);
            // Locked translation axes take no part of the push (AxisLocks); rotation locks are in the inertia.
            AxisLocks locks = b.Locks[slot] & AxisLocks.Linear;
            float linear = locks == 0 ? b.InverseMass[slot] : b.InverseMass[slot] * Vector3.Dot(AxisLockMath.LinearMask(locks), direction * direction);
            return linear + Vector3.Dot(rn, b.InverseInertiaWorld[slot] * rn);
        }

        /// <summary>
        /// The inverse mass matrix of a dynamic body at <paramref name="point"/>: the change of
        /// that point's velocity per unit impulse there, M^-1 + [r]^T I^-1 [r]; zero for static
        /// and kinematic bodies.
        /// </summary>
        public Mat3 PointInverseMass(int slot, Vector3 point)
        {
            BodyStorage b = _bodies;
            if (b.Type[slot] != BodyType.Dynamic) return Mat3.Zero;
            Mat3 skew = Mat3.Skew(point - b.Center[slot]);
            Vector3 linear = AxisLockMath.MaskLinear(new Vector3(b.InverseMass[slot]), b.Locks[slot]);
            return Mat3.Diagonal(linear) + skew.Transposed * (b.InverseInertiaWorld[slot] * skew);
        }

        /// <summary>The velocity of the body's material point at <paramref name="point"/>, m/s.</summary>
        public Vector3 PointVelocity(int slot, Vector3 point)
        {
            BodyStorage b = _bodies;
            if (b.Type[slot] == BodyType.Static) return Vector3.Zero;
            return b.LinearVelocity[slot] + Vector3.Cross(b.AngularVelocity[slot], point - b.Center[slot]);
        }

        /// <summary>Applies a position impulse <paramref name="impulse"/> (kg m) at <paramref name="point"/> to a dynamic body.</summary>
        public void Push(int slot, Vector3 point, Vector3 impulse, float h)
        {
            BodyStorage b = _bodies;
            if (b.Type[slot] != BodyType.Dynamic) return;
            PushSum(slot, impulse, Vector3.Cross(point - b.Center[slot], impulse), h);
        }

        /// <summary>Adds a position impulse at <paramref name="point"/> to a sum about the body's centre (for one <see cref="PushSum"/> of the sum).</summary>
        public void Accumulate(int slot, Vector3 point, Vector3 impulse, ref Vector3 linear, ref Vector3 angular)
        {
            linear += impulse;
            angular += Vector3.Cross(point - _bodies.Center[slot], impulse);
        }

        /// <summary>Applies a position impulse <paramref name="linear"/> (kg m) and its moment about the centre <paramref name="angular"/> (kg m^2) to a dynamic body.</summary>
        public void PushSum(int slot, Vector3 linear, Vector3 angular, float h)
        {
            BodyStorage b = _bodies;
            if (b.Type[slot] != BodyType.Dynamic) return;
            int e = _entryOfSlot[slot];
            if (e < 0) return; // only tracked bodies are pushed (every candidate is tracked)
            Vector3 dx = AxisLockMath.MaskLinear(linear * b.InverseMass[slot], b.Locks[slot]);
            Vector3 dTheta = b.InverseInertiaWorld[slot] * angular;
            float invH = 1f / h;
            Quaternion dq = Rotation.FromRotationVector(dTheta);
            b.Center[slot] += dx;
            b.Rotation[slot] = Quaternion.Normalize(dq * b.Rotation[slot]);
            b.LinearVelocity[slot] += dx * invH;
            b.AngularVelocity[slot] += dTheta * invH;
            b.SyncOriginFromCenter(slot);
            b.UpdateWorldInertia(slot);
            b.Awake[slot] = true;
            b.SleepTime[slot] = 0; // soft bodies never sleep: what they push stays awake with them (asleep it would lose its weight and be pushed up)
        }

        /// <summary>
        /// Applies a velocity impulse <paramref name="impulse"/> (kg m/s) at <paramref name="point"/>
        /// to a dynamic body: its velocity changes now and its pose through the later substeps.
        /// </summary>
        public void Kick(int slot, Vector3 point, Vector3 impulse)
        {
            BodyStorage b = _bodies;
            if (b.Type[slot] != BodyType.Dynamic) return;
            int e = _entryOfSlot[slot];
            if (e < 0) return;
            Vector3 dv = AxisLockMath.MaskLinear(impulse * b.InverseMass[slot], b.Locks[slot]);
            Vector3 dw = b.InverseInertiaWorld[slot] * Vector3.Cross(point - b.Center[slot], impulse);
            b.LinearVelocity[slot] += dv;
            b.AngularVelocity[slot] += dw;
            b.Awake[slot] = true;
            b.SleepTime[slot] = 0; // soft bodies never sleep: what they push stays awake with them (asleep it would lose its weight and be pushed up)
        }

        // The tracked bodies' velocities when Snapshot was last called.
        Vector3[] _savedLinear = Array.Empty<Vector3>();
        Vector3[] _savedAngular = Array.Empty<Vector3>();

        /// <summary>Remembers every tracked body's velocity, for <see cref="Changed"/>.</summary>
        public void Snapshot()
        {
            if (_savedLinear.Length < _count)
            {
                _savedLinear = new Vector3[_slot.Length];
                _savedAngular = new Vector3[_slot.Length];
            }
            BodyStorage b = _bodies;
            for (int e = 0; e < _count; e++)
            {
                _savedLinear[e] = b.LinearVelocity[_slot[e]];
                _savedAngular[e] = b.AngularVelocity[_slot[e]];
            }
        }

        /// <summary>Tracked bodies (entries 0 .. Count - 1).</summary>
        public int Count => _count;

        /// <summary>The body slot of tracked entry <paramref name="e"/>.</summary>
        public int SlotOf(int e) => _slot[e];

        /// <summary>True when entry <paramref name="e"/> is a dynamic body whose velocity changed since <see cref="Snapshot"/>.</summary>
        public bool Changed(int e)
        {
            int slot = _slot[e];
            return _bodies.Type[slot] == BodyType.Dynamic
                && (_bodies.LinearVelocity[slot] != _savedLinear[e] || _bodies.AngularVelocity[slot] != _savedAngular[e]);
        }

        /// <summary>
        /// The kinetic and gravitational energy of the tracked dynamic bodies, J (gravity
        /// <paramref name="gravity"/> times each body's gravity scale).
        /// </summary>
        public double Energy(Vector3 gravity)
        {
            BodyStorage b = _bodies;
            double e = 0;
            for (int k = 0; k < _count; k++)
            {
                int slot = _slot[k];
                if (b.Type[slot] != BodyType.Dynamic) continue;
                e += b.Mass[slot] * (0.5 * b.LinearVelocity[slot].LengthSquared() - b.GravityScale[slot] * Vector3.Dot(gravity, b.Center[slot]));
                e += RotationalEnergy(slot);
            }
            return e;
        }

        /// <summary>
        /// The energy a substep of <paramref name="h"/> may show in the bodies whose velocity
        /// changed since <see cref="Snapshot"/> without any being made, J: m |a h|^2 plus
        /// (alpha h)^T I (alpha h) per body, with a and alpha the rigid solve's accelerations.
        /// The bodies' velocity step (v += a h, x += v h) comes before a soft body's substep and
        /// a contact's push after it, and that split alone shows up to 1/2 m |a h|^2 per substep
        /// for a body resting on a soft body (the push lifts it by the step gravity lowered it,
        /// at the velocity gravity gave it): counted as a gain, a 2000 kg plate resting on an
        /// 8 kg cube had its motion scaled down every substep and settled 1.8 % off its closed-form
        /// strain. Twice that is allowed.
        /// </summary>
        public double Slack(float h)
        {
            double slack = 0;
            for (int e = 0; e < _count; e++)
            {
                if (!Changed(e)) continue;
                int slot = _slot[e];
                Vector3 dv = _acceleration[e] * h;
                slack += _bodies.Mass[slot] * dv.LengthSquared() + 2 * RotationalEnergy(slot, _angularAcceleration[e] * h);
            }
            return slack;
        }

        /// <summary>1/2 w^T I w of a dynamic body (about its free rotation axes), J.</summary>
        public double RotationalEnergy(int slot) => RotationalEnergy(slot, _bodies.AngularVelocity[slot]);

        // 1/2 w^T I w for angular velocity w of the body in slot (about its free rotation axes).
        double RotationalEnergy(int slot, Vector3 w)
        {
            BodyStorage b = _bodies;
            if (w == Vector3.Zero) return 0;
            Vector3 locked = Vector3.One - AxisLockMath.AngularMask(b.Locks[slot]);
            if (!(b.InverseInertiaWorld[slot] + Mat3.Diagonal(locked)).TryInvert(out Mat3 inertia)) return 0;
            return 0.5 * Vector3.Dot(w, inertia * w);
        }

        void Grow(int capacity)
        {
            Array.Resize(ref _slot, capacity);
            Array.Resize(ref _startCenter, capacity);
            Array.Resize(ref _startRotation, capacity);
            Array.Resize(ref _endCenter, capacity);
            Array.Resize(ref _endRotation, capacity);
            Array.Resize(ref _endOrigin, capacity);
            Array.Resize(ref _acceleration, capacity);
            Array.Resize(ref _angularAcceleration, capacity);
            Array.Resize(ref _correction, capacity);
            Array.Resize(ref _angularCorrection, capacity);
            Array.Resize(ref _endLinear, capacity);
            Array.Resize(ref _endAngular, capacity);
            Array.Resize(ref _carriedBy, capacity);
            Array.Resize(ref _lastCarrier, capacity);
        }
    }
}
