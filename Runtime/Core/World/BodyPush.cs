using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    /// <summary>
    /// One push of <see cref="World.AddForce"/> or <see cref="World.AddTorque"/> (a force,
    /// acceleration, impulse or velocity change): the per-slot column it changes (the force or
    /// torque accumulated for the step, or a velocity) and the value it leaves there, worked
    /// out before anything changes so that a push beyond the limits throws with nothing done.
    /// </summary>
    internal readonly struct BodyPush
    {
        readonly Vector3[] _column;
        readonly Vector3 _value;
        readonly float _limit;
        readonly string _what;

        /// <summary>A push that leaves <paramref name="value"/> in <paramref name="column"/>, allowed up to <paramref name="limit"/>; <paramref name="what"/> names the value in errors.</summary>
        public BodyPush(Vector3[] column, Vector3 value, float limit, string what)
        {
            _column = column;
            _value = value;
            _limit = limit;
            _what = what;
        }

        /// <summary>
        /// Throws when the value would be non-finite or beyond its limit (<see cref="Limits.MaxForce"/>
        /// for an accumulated force or torque, <see cref="Limits.MaxInputSpeed"/> for a velocity).
        /// The message is built only on failure: AddForce runs every frame and must not allocate.
        /// </summary>
        public void Check(string name)
        {
            if (Validate.IsFinite(_value) && Limits.Length(_value) <= _limit) return;
            throw new ArgumentException($"{name}: {_what} would be {_value}, beyond {_limit:G} (Limits.MaxForce/MaxInputSpeed).", name);
        }

        /// <summary>Stores the value in slot <paramref name="i"/>.</summary>
        public void Apply(int i) => _column[i] = _value;
    }
}
