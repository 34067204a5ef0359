using System;
using System.Numerics;

namespace Fulcrum.Components
{
    public sealed partial class Rigidbody
    {
        float _maxLinearVelocity = float.PositiveInfinity;
        float _maxAngularVelocity = float.PositiveInfinity;
        bool _detectCollisions = true;

        /// <summary>
        /// The largest speed of the centre of mass, m/s (&gt; 0; infinity = no cap beyond the
        /// world's <see cref="WorldSettings.MaxLinearSpeed"/>). Enforced before and after each
        /// step, so the body never leaves a step faster. Default: infinity (Unity: 1e16).
        /// </summary>
        public float maxLinearVelocity
        {
            get => _maxLinearVelocity;
            set => SetCap(ref _maxLinearVelocity, value, nameof(maxLinearVelocity));
        }

        /// <summary>
        /// The largest angular speed, rad/s (&gt; 0; infinity = no cap). Enforced before and after
        /// each step. Default: infinity. Departure from Unity, whose default is 7 rad/s (50 from
        /// Unity 6): Fulcrum does not slow fast spinners unless asked; set 7 to match an old project.
        /// </summary>
        public float maxAngularVelocity
        {
            get => _maxAngularVelocity;
            set => SetCap(ref _maxAngularVelocity, value, nameof(maxAngularVelocity));
        }

        /// <summary>
        /// Whether the body's colliders touch anything (Unity's detectCollisions): false keeps
        /// them for mass and for queries but gives them no contacts or trigger overlaps; the
        /// contacts they had end, and the body wakes. Default: true.
        /// </summary>
        public bool detectCollisions
        {
            get => _detectCollisions;
            set
            {
                if (!SetFlag(ref _detectCollisions, value, nameof(detectCollisions))) return;
                Collider[] attached = Colliders.ToArray();
                foreach (Collider c in attached) c.Rebuild();
                if (HasBody) World.GetBody(_body).WakeUp(); // a resting body must notice its support is gone
            }
        }

        internal bool HasSpeedCaps => _maxLinearVelocity < float.PositiveInfinity || _maxAngularVelocity < float.PositiveInfinity;

        // Scales each velocity down to its cap (direction kept).
        internal void ClampSpeeds(BodyStorage b, int i)
        {
            b.LinearVelocity[i] = Cap(b.LinearVelocity[i], _maxLinearVelocity);
            b.AngularVelocity[i] = Cap(b.AngularVelocity[i], _maxAngularVelocity);
        }

        static Vector3 Cap(Vector3 v, float max)
        {
            float s = v.LengthSquared();
            return s > max * max ? v * (max / MathF.Sqrt(s)) : v;
        }

        // The setter of either cap: a cap is > 0 (infinity for none); refused mid-step, then
        // stored (ClampSpeeds reads it at the next step).
        void SetCap(ref float cap, float value, string field)
        {
            if (!(value > 0) || float.IsNaN(value))
                throw new ArgumentException($"{this}: {field} must be > 0 (infinity for no cap), got {value}.", field);
            ThrowIfStepping(field);
            cap = value;
        }
    }
}
