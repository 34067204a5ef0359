using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    public sealed partial class Rigidbody
    {
        /// <summary>Unity 2021.3-2022's name of <see cref="linearVelocity"/> (Unity 6 renamed it).</summary>
        public Vector3 velocity
        {
            get => linearVelocity;
            set => linearVelocity = value;
        }

        /// <summary>Unity 2021.3-2022's name of <see cref="linearDamping"/>, 1/s.</summary>
        public float drag
        {
            get => linearDamping;
            set => linearDamping = value;
        }

        /// <summary>Unity 2021.3-2022's name of <see cref="angularDamping"/>, 1/s.</summary>
        public float angularDrag
        {
            get => angularDamping;
            set => angularDamping = value;
        }

        /// <summary>
        /// Whether physics may turn the body: true sets all three rotation bits of
        /// <see cref="constraints"/> (infinite inertia in the solver), false clears them
        /// (the position bits are kept), as Unity's freezeRotation does.
        /// </summary>
        public bool freezeRotation
        {
            get => (_constraints & RigidbodyConstraints.FreezeRotation) == RigidbodyConstraints.FreezeRotation;
            set => constraints = value ? _constraints | RigidbodyConstraints.FreezeRotation : _constraints & ~RigidbodyConstraints.FreezeRotation;
        }

        /// <summary>
        /// Applies an explosion's push (Unity's AddExplosionForce): nothing when the body's
        /// bounds are farther than <paramref name="explosionRadius"/> from
        /// <paramref name="explosionPosition"/>; otherwise a force of
        /// <paramref name="explosionForce"/> scaled by (1 - distance / radius), where distance is
        /// from the explosion to the nearest point of the body's bounds (radius 0: no fall-off,
        /// any distance). It points from the explosion centre, lowered by
        /// <paramref name="upwardsModifier"/> metres (so that things are thrown up), to the
        /// centre of mass, and acts there (no torque). <paramref name="mode"/> as in
        /// <see cref="AddForce(Vector3, ForceMode)"/>.
        /// </summary>
        public void AddExplosionForce(float explosionForce, Vector3 explosionPosition, float explosionRadius,
            float upwardsModifier = 0f, ForceMode mode = ForceMode.Force)
        {
            if (!float.IsFinite(explosionForce) || Math.Abs(explosionForce) > Limits.MaxForce)
                throw new ArgumentException($"{this}: explosionForce must be finite with magnitude at most {Limits.MaxForce:G}, got {explosionForce}.", nameof(explosionForce));
            FieldCheck.Position(explosionPosition, this, nameof(explosionPosition));
            FieldCheck.NonNegative(explosionRadius, this, nameof(explosionRadius));
            if (!float.IsFinite(upwardsModifier))
                throw new ArgumentException($"{this}: upwardsModifier must be finite, got {upwardsModifier}.", nameof(upwardsModifier));
            ThrowIfStepping(nameof(AddExplosionForce));
            if (!HasBody || _isKinematic) return;
            Vector3 center = World.GetBody(_body).CenterOfMass;
            float scale = 1f;
            if (explosionRadius > 0)
            {
                Aabb box = Bounds();
                Vector3 nearest = box.IsValid ? Vector3.Clamp(explosionPosition, box.Min, box.Max) : center;
                float distance = Vector3.Distance(nearest, explosionPosition);
                if (distance > explosionRadius) return;
                scale = 1f - distance / explosionRadius;
            }
            Vector3 from = explosionPosition - new Vector3(0, upwardsModifier, 0);
            Vector3 d = center - from;
            float length = d.Length();
            // At the centre itself the direction is undefined: Unity pushes up, and so does Fulcrum.
            Vector3 direction = length > 1e-6f ? d / length : Vector3.UnitY;
            World.AddForce(_body, direction * (explosionForce * scale), mode);
        }

        // The union of the attached colliders' world bounds (empty without colliders).
        Aabb Bounds()
        {
            Aabb box = Aabb.Empty;
            for (int k = 0; k < Colliders.Count; k++)
                if (Colliders[k].HasShape) box = Aabb.Union(box, Colliders[k].bounds);
            return box;
        }
    }
}
