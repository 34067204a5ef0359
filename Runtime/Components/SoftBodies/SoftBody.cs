using System;
using Fulcrum.Mathematics;
using Fulcrum.SoftBodies;

namespace Fulcrum.Components
{
    /// <summary>
    /// A Neo-Hookean soft body (Fulcrum.SoftBodies) on an entity: the <see cref="mesh"/> is placed
    /// at the entity's pose when the component goes live and then simulated in world space;
    /// it collides with the colliders of the scene. The transform stays where it was (read the
    /// deformed shape from <see cref="body"/>: Positions, ComputeStats().Centroid).
    /// An entity carries either a SoftBody or a Rigidbody, not both. Changing the mesh or the
    /// material of a live soft body rebuilds it at rest.
    /// </summary>
    public sealed partial class SoftBody : Component
    {
        SoftMesh? _mesh;
        NeoHookeanMaterial _material = NeoHookeanMaterial.Default;
        float _friction = 0.5f;
        SoftBodyHandle _handle;

        /// <summary>The tetrahedral (or cloth) mesh in the entity's frame. Required for a body to exist.</summary>
        public SoftMesh? mesh
        {
            get => _mesh;
            set { ThrowIfStepping(nameof(mesh)); _mesh = value; Rebuild(); }
        }

        /// <summary>The material (Young's modulus, Poisson ratio, density). Default: NeoHookeanMaterial.Default.</summary>
        public NeoHookeanMaterial material
        {
            get => _material;
            set
            {
                try { value.Validate(); }
                catch (ArgumentException e) { throw new ArgumentException($"{this}: material is invalid: {e.Message}", nameof(material), e); }
                ThrowIfStepping(nameof(material));
                _material = value;
                Rebuild();
            }
        }

        /// <summary>Coulomb friction against colliders, &gt;= 0. Default: 0.5.</summary>
        public float friction
        {
            get => _friction;
            set
            {
                SetNonNegative(ref _friction, value, nameof(friction));
                if (!_handle.IsNone) body!.Friction = value;
            }
        }

        /// <summary>The soft body's handle in the world; None while there is none.</summary>
        public SoftBodyHandle handle => _handle;

        /// <summary>The simulated soft body (positions, velocities, statistics), or null.</summary>
        public Fulcrum.SoftBodies.SoftBody? body => _handle.IsNone ? null : scene.world.GetSoftBody(_handle);

        internal override void OnAdded()
        {
            if (entity.GetComponent<Rigidbody>() != null)
                throw new InvalidOperationException($"Entity '{name}' has a Rigidbody: it cannot also carry a SoftBody.");
            if (entity.GetComponent<SoftBody>() != this)
                throw new InvalidOperationException($"Entity '{name}' already has a SoftBody: an entity carries at most one.");
        }

        internal override void Activate() => Build();

        internal override void Deactivate() => Remove();

        void Build()
        {
            if (_mesh == null || !_handle.IsNone || !IsLive) return;
            Pose pose = transform.WorldPose;
            SoftBodyDef def = SoftBodyDef.Of(_mesh, _material, pose.Position);
            def.Rotation = pose.Rotation;
            def.Friction = _friction;
            def.Layer = entity.layer;
            def.CollidesWith = scene.CollisionMaskOf(entity.layer);
            def.Name = name;
            ApplySettings(ref def);
            _handle = scene.world.CreateSoftBody(def);
        }

        void Remove()
        {
            if (_handle.IsNone) return;
            if (scene.world.IsValid(_handle)) scene.world.DestroySoftBody(_handle);
            _handle = default;
        }

        void Rebuild()
        {
            Remove();
            Build();
        }
    }
}
