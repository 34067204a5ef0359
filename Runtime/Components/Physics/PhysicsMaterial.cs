using System;
using System.Collections.Generic;

namespace Fulcrum.Components
{
    /// <summary>
    /// Surface properties shared by colliders, like Unity's PhysicsMaterial. Combine modes
    /// use Core's <see cref="CombineMode"/>, which has Unity's priority order (Average &lt;
    /// Minimum &lt; Multiply &lt; Maximum: the higher of the two colliders' modes wins).
    /// Changing a value updates every collider that uses the material.
    /// Departure from Unity: Fulcrum has one Coulomb coefficient per contact, so
    /// <see cref="dynamicFriction"/> is used for sliding and sticking alike;
    /// <see cref="staticFriction"/> is kept for round-tripping but not simulated.
    /// </summary>
    public sealed class PhysicsMaterial
    {
        float _dynamicFriction = 0.6f;
        float _staticFriction = 0.6f;
        float _bounciness;
        CombineMode _frictionCombine = CombineMode.Average;
        CombineMode _bounceCombine = CombineMode.Average;
        internal readonly List<Collider> Users = new List<Collider>();

        /// <summary>A material with Unity's defaults (friction 0.6, bounciness 0, Average).</summary>
        public PhysicsMaterial() : this("PhysicsMaterial") { }

        /// <summary>A named material with Unity's defaults.</summary>
        public PhysicsMaterial(string name)
        {
            this.name = name ?? throw new ArgumentNullException(nameof(name));
        }

        /// <summary>The name (used in errors).</summary>
        public string name { get; set; }

        /// <summary>Coulomb friction coefficient used by Fulcrum, &gt;= 0. Default: 0.6.</summary>
        public float dynamicFriction
        {
            get => _dynamicFriction;
            set { Check(value, nameof(dynamicFriction), false); _dynamicFriction = value; Changed(); }
        }

        /// <summary>Unity's static friction, &gt;= 0: stored, not simulated (see the class remarks). Default: 0.6.</summary>
        public float staticFriction
        {
            get => _staticFriction;
            set { Check(value, nameof(staticFriction), false); _staticFriction = value; }
        }

        /// <summary>Coefficient of restitution in [0, 1]. Default: 0.</summary>
        public float bounciness
        {
            get => _bounciness;
            set { Check(value, nameof(bounciness), true); _bounciness = value; Changed(); }
        }

        /// <summary>How friction combines with the other collider's. Default: Average.</summary>
        public CombineMode frictionCombine
        {
            get => _frictionCombine;
            set { CheckMode(value, nameof(frictionCombine)); _frictionCombine = value; Changed(); }
        }

        /// <summary>How bounciness combines with the other collider's. Default: Average.</summary>
        public CombineMode bounceCombine
        {
            get => _bounceCombine;
            set { CheckMode(value, nameof(bounceCombine)); _bounceCombine = value; Changed(); }
        }

        /// <inheritdoc/>
        public override string ToString() => $"PhysicsMaterial '{name}'";

        void Check(float v, string field, bool unit)
        {
            if (!(float.IsFinite(v) && v >= 0 && (!unit || v <= 1)))
                throw new ArgumentException($"{this}: {field} must be {(unit ? "in [0, 1]" : "finite and >= 0")}, got {v}.", field);
        }

        void CheckMode(CombineMode m, string field)
        {
            if (m > CombineMode.Maximum) throw new ArgumentException($"{this}: {field} {m} is not a combine mode.", field);
        }

        void Changed()
        {
            for (int k = 0; k < Users.Count; k++) Users[k].ApplyMaterial();
        }
    }
}
