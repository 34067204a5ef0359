using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The rigid bodies a soft body touches during the soft-body stage. The rigid solve has
    /// already moved them over the whole step; here they are walked along that motion substep
    /// by substep (centre linearly, rotation by slerp, from the start-of-step pose), so a
    /// contact builds up as gradually as the soft body's own motion. XPBD corrections pushed
    /// onto a dynamic body (a position impulse P at a point) move it by P/m and
    /// I^-1 (r x P) and change its velocity by the same over h, exactly the momentum the
    /// vertex loses; the velocity change also carries it on through the later substeps.
    /// Writes body pose, velocity and world inertia in <see cref="BodyStorage"/>.
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
        Vector3[] _offset = Array.Empty<Vector3>();
        Quaternion[] _rotationOffset = Array.Empty<Quaternion>();
        Vector3[] _linearDrift = Array.Empty<Vector3>();
        Vector3[] _angularDrift = Array.Empty<Vector3>();
        int _count;

        /// <summary>Forgets last step's bodies.</summary>
        public void Begin(BodyStorage bodies)
        {
            _bodies = bodies;
            if (_entryOfSlot.Length < bodies.SlotCount)
            {
                int old = _entryOfSlot.Length;
                Array.Resize(ref _entryOfSlot, Math.Max(bodies.SlotCount, 2 * old));
                for (int i = old; i < _entryOfSlot.Length; i++) _entryOfSlot[i] = -1;
            }
            for (int k = 0; k < _count; k++) _entryOfSlot[_slot[k]] = -1;
            _count = 0;
        }

        /// <summary>Starts walking a moving body through the substeps (static bodies need nothing).</summary>
        public void Track(int slot)
        {
            if (_bodies.Type[slot] == BodyType.Static || _entryOfSlot[slot] >= 0) return;
            if (_count == _slot.Length) Grow(Math.Max(8, 2 * _count));
            int e = _count++;
            _entryOfSlot[slot] = e;
            _slot[e] = slot;
            BodyStorage b = _bodies;
            _startRotation[e] = b.PreviousRotation[slot];
            _startCenter[e] = b.PreviousPosition[slot] + Vector3.Transform(b.LocalCenter[slot], b.PreviousRotation[slot]);
            _endCenter[e] = b.Center[slot];
            _endRotation[e] = b.Rotation[slot];
            _offset[e] = Vector3.Zero;
            _rotationOffset[e] = Quaternion.Identity;
            _linearDrift[e] = Vector3.Zero;
            _angularDrift[e] = Vector3.Zero;
        }

        /// <summary>Puts every tracked body where it is at fraction <paramref name="t"/> of the step (plus what the soft bodies did to it).</summary>
        public void BeginSubstep(float t, float h)
        {
            BodyStorage b = _bodies;
            for (int e = 0; e < _count; e++)
            {
                int slot = _slot[e];
                _offset[e] += _linearDrift[e] * h;
                _rotationOffset[e] = Rotation.Integrate(_rotationOffset[e], _angularDrift[e], h);
                b.Center[slot] = Vector3.Lerp(_startCenter[e], _endCenter[e], t) + _offset[e];
                b.Rotation[slot] = Quaternion.Normalize(_rotationOffset[e] * Quaternion.Slerp(_startRotation[e], _endRotation[e], t));
                b.SyncOriginFromCenter(slot);
                b.UpdateWorldInertia(slot);
            }
        }

        /// <summary>
        /// The inverse mass a dynamic body shows along <paramref name="direction"/> (unit) at
        /// <paramref name="point"/>: 1/m + (r x n) . I^-1 (r x n); 0 for static and kinematic bodies.
        /// </summary>
        public float InverseMassAt(int slot, Vector3 point, Vector3 direction)
        {
            BodyStorage b = _bodies;
            if (b.Type[slot] != BodyType.Dynamic) return 0f;
            Vector3 rn = Vector3.Cross(point - b.Center[slot], direction);
            return b.InverseMass[slot] + Vector3.Dot(rn, b.InverseInertiaWorld[slot] * rn);
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
            int e = _entryOfSlot[slot];
            if (e < 0) return; // only tracked bodies are pushed (every candidate is tracked)
            Vector3 dx = impulse * b.InverseMass[slot];
            Vector3 dTheta = b.InverseInertiaWorld[slot] * Vector3.Cross(point - b.Center[slot], impulse);
            float invH = 1f / h;
            _offset[e] += dx;
            Quaternion dq = Rotation.FromRotationVector(dTheta);
            _rotationOffset[e] = Quaternion.Normalize(dq * _rotationOffset[e]);
            _linearDrift[e] += dx * invH;
            _angularDrift[e] += dTheta * invH;
            b.Center[slot] += dx;
            b.Rotation[slot] = Quaternion.Normalize(dq * b.Rotation[slot]);
            b.LinearVelocity[slot] += dx * invH;
            b.AngularVelocity[slot] += dTheta * invH;
            b.SyncOriginFromCenter(slot);
            b.UpdateWorldInertia(slot);
            b.Awake[slot] = true;
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
            Vector3 dv = impulse * b.InverseMass[slot];
            Vector3 dw = b.InverseInertiaWorld[slot] * Vector3.Cross(point - b.Center[slot], impulse);
            _linearDrift[e] += dv;
            _angularDrift[e] += dw;
            b.LinearVelocity[slot] += dv;
            b.AngularVelocity[slot] += dw;
            b.Awake[slot] = true;
        }

        void Grow(int capacity)
        {
            Array.Resize(ref _slot, capacity);
            Array.Resize(ref _startCenter, capacity);
            Array.Resize(ref _startRotation, capacity);
            Array.Resize(ref _endCenter, capacity);
            Array.Resize(ref _endRotation, capacity);
            Array.Resize(ref _offset, capacity);
            Array.Resize(ref _rotationOffset, capacity);
            Array.Resize(ref _linearDrift, capacity);
            Array.Resize(ref _angularDrift, capacity);
        }
    }
}
