using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    /// <summary>
    /// The base of the collider components: one shape in the world. A collider belongs to the
    /// nearest <see cref="Rigidbody"/> on its entity or an ancestor (colliders on children
    /// build a compound, as in Unity); with none it is static (its own static body, which
    /// follows the transform when user code moves it — expensive, as in Unity).
    /// Changing the geometry, <see cref="isTrigger"/> or the layer rebuilds the shape (the
    /// contacts it had end). Sizes must be &gt; 0: a zero or negative size throws
    /// (Unity accepts flat boxes; Fulcrum's shapes need volume).
    /// </summary>
    public abstract partial class Collider : Component
    {
        bool _enabled = true;
        bool _isTrigger;
        Vector3 _center;
        PhysicsMaterial? _material;
        ShapeHandle _shape;
        BodyHandle _staticBody;
        Rigidbody? _attached;

        internal long SeenTransformVersion;

        /// <summary>Disabled colliders have no shape in the world. Default: true.</summary>
        public bool enabled
        {
            get => _enabled;
            set
            {
                ThrowIfDestroyed();
                if (value == _enabled) return;
                ThrowIfStepping(nameof(enabled));
                _enabled = value;
                if (!IsLive) return;
                if (value) Build();
                else Remove();
            }
        }

        /// <summary>A trigger reports overlaps (OnTriggerEnter/Stay/Exit) and has no physical response. Default: false.</summary>
        public bool isTrigger
        {
            get => _isTrigger;
            set
            {
                if (SetFlag(ref _isTrigger, value, nameof(isTrigger))) Rebuild();
            }
        }

        /// <summary>The shape's centre in the entity's frame, metres. Default: 0.</summary>
        public Vector3 center
        {
            get => _center;
            set
            {
                FieldCheck.Finite(value, this, "center");
                SetShapeField(ref _center, value, nameof(center));
            }
        }

        /// <summary>The material (shared by reference), or null for the defaults (friction 0.6, bounciness 0, Average).</summary>
        public PhysicsMaterial? sharedMaterial
        {
            get => _material;
            set
            {
                ThrowIfStepping(nameof(sharedMaterial));
                if (value == _material) return;
                _material?.Users.Remove(this);
                _material = value;
                if (value != null && !isDestroyed) value.Users.Add(this);
                ApplyMaterial();
            }
        }

        /// <summary>The rigidbody this collider is part of, or null for a static collider.</summary>
        public Rigidbody? attachedRigidbody => _attached;

        /// <summary>The shape in <see cref="PhysicsScene.world"/>; None while disabled or inactive.</summary>
        public ShapeHandle shape => _shape;

        /// <summary>World bounds of the shape as of the last step (or its creation); empty without a shape.</summary>
        public Aabb bounds => _shape.IsNone ? Aabb.Empty : scene.world.GetShapeAabb(_shape);

        /// <summary>The body that carries the shape (the rigidbody's or the collider's own static body); None without a shape.</summary>
        internal BodyHandle Body => _attached != null ? _attached.body : _staticBody;

        internal bool HasShape => !_shape.IsNone;

        /// <summary>The geometry in the collider's own frame; throws naming the bad field.</summary>
        internal abstract ShapeGeometry BuildGeometry();

        /// <summary>False while the collider has nothing to build from (a MeshCollider without a mesh): it then has no shape.</summary>
        internal virtual bool HasGeometry => true;

        /// <summary>The shape's pose in the entity frame: <see cref="center"/> and, for capsules, the axis.</summary>
        internal virtual Pose LocalShapePose => new Pose(_center, Quaternion.Identity);

        /// <summary>Throws when the collider cannot live on <paramref name="body"/> (non-convex meshes on rigidbodies).</summary>
        internal virtual void CheckBody(Rigidbody? body) { }

        internal override void Activate()
        {
            if (_enabled) Build();
        }

        internal override void Deactivate()
        {
            Remove();
            scene.ForgetIgnores(this);
        }

        internal override void Teardown()
        {
            _material?.Users.Remove(this);
            scene.ForgetIgnores(this);
        }

        internal void OnLayerChanged() => Rebuild();

        /// <summary>
        /// The tail of every geometry setter (size, radius, height, axis, centre): refuses the
        /// change while the world steps, stores <paramref name="value"/> and replaces the live
        /// shape. The caller validates the value first, so a bad value is reported as such even
        /// mid-step.
        /// </summary>
        internal void SetShapeField<T>(ref T field, T value, string member)
        {
            ThrowIfStepping(member);
            field = value;
            Rebuild();
        }

        /// <summary>A size setter (radius, height): checked against <see cref="Limits"/>' shape sizes, then <see cref="SetShapeField{T}"/>.</summary>
        internal void SetSize(ref float field, float value, string member)
        {
            FieldCheck.Size(value, this, member);
            SetShapeField(ref field, value, member);
        }

        // Geometry or settings changed: a live shape is replaced (validated before the old one goes).
        internal void Rebuild()
        {
            if (!HasShape) return;
            BuildGeometry();
            Remove();
            Build();
        }

        internal void Build()
        {
            if (HasShape || !HasGeometry) return;
            PhysicsScene s = scene;
            World w = s.world;
            Rigidbody? rb = FindRigidbody();
            CheckBody(rb);
            ShapeDef def = ShapeDef.Of(BuildGeometry());
            def.IsSensor = _isTrigger;
            def.Layer = entity.layer;
            def.CollidesWith = rb != null && !rb.detectCollisions ? 0u : s.CollisionMaskOf(entity.layer);
            def.UserData = 0;
            WriteMaterial(ref def);
            if (rb != null)
            {
                def.LocalPose = transform.PoseRelativeTo(rb.transform) * LocalShapePose;
                _shape = w.AddShape(rb.body, def);
                _attached = rb;
                rb.Colliders.Add(this);
                rb.ApplyMass();
                SeenTransformVersion = transform.VersionBelow(rb.transform);
            }
            else
            {
                Pose pose = transform.WorldPose;
                BodyDef body = BodyDef.Static(pose.Position);
                body.Rotation = pose.Rotation;
                body.Name = name;
                _staticBody = w.CreateBody(body);
                def.LocalPose = LocalShapePose;
                try { _shape = w.AddShape(_staticBody, def); }
                catch { w.DestroyBody(_staticBody); _staticBody = default; throw; }
                SeenTransformVersion = transform.HierarchyVersion;
            }
            s.MapShape(_shape, this);
            s.ReapplyIgnores(this);
        }

        internal void Remove()
        {
            if (!HasShape) return;
            World w = scene.world;
            scene.UnmapShape(_shape);
            if (_attached != null)
            {
                Rigidbody rb = _attached;
                if (w.IsValid(_shape)) w.RemoveShape(_shape);
                rb.Colliders.Remove(this);
                _attached = null;
                rb.ApplyMass();
            }
            else if (!_staticBody.IsNone)
            {
                w.DestroyBody(_staticBody);
                _staticBody = default;
            }
            _shape = default;
        }

        // The nearest live rigidbody on this entity or above it.
        internal Rigidbody? FindRigidbody()
        {
            for (Transform? t = transform; t != null; t = t.parent)
            {
                Rigidbody? rb = t.entity.GetComponent<Rigidbody>();
                if (rb != null && rb.HasBody) return rb;
            }
            return null;
        }

        /// <summary>True when the transform moved relative to the body since the shape was built (user code moved it).</summary>
        internal bool TransformChanged =>
            _attached != null
                ? transform.VersionBelow(_attached.transform) != SeenTransformVersion
                : transform.HierarchyVersion != SeenTransformVersion;

        internal void ApplyMaterial()
        {
            if (!HasShape) return;
            ShapeDef d = default;
            WriteMaterial(ref d);
            ShapeStorage st = scene.world.Shapes;
            int i = _shape.Index;
            st.Friction[i] = d.Friction;
            st.Restitution[i] = d.Restitution;
            st.FrictionCombine[i] = d.FrictionCombine;
            st.RestitutionCombine[i] = d.RestitutionCombine;
        }

        void WriteMaterial(ref ShapeDef def)
        {
            PhysicsMaterial? m = _material;
            def.Friction = m?.dynamicFriction ?? 0.6f;
            def.Restitution = m?.bounciness ?? 0f;
            def.FrictionCombine = m?.frictionCombine ?? CombineMode.Average;
            def.RestitutionCombine = m?.bounceCombine ?? CombineMode.Average;
        }
    }
}
