using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    /// <summary>
    /// The base of the joint components (Unity's Joint): ties this entity's
    /// <see cref="Rigidbody"/> to <see cref="connectedBody"/> (or to the world when null).
    /// <see cref="anchor"/> is in this entity's frame; <see cref="connectedAnchor"/> in the
    /// connected body's frame (a world point without one) and, with
    /// <see cref="autoConfigureConnectedAnchor"/>, computed so that the joint starts satisfied.
    /// The joint takes the bodies' pose when it is built (on activation) as its rest pose.
    /// Breaking: when the force exceeds <see cref="breakForce"/> or the torque
    /// <see cref="breakTorque"/>, behaviours on the entity get OnJointBreak once and the joint
    /// component is destroyed at the end of the frame, as in Unity.
    /// Departures from Unity: changing <see cref="connectedBody"/>, the anchors or the axis of a
    /// built joint rebuilds it, which takes the current pose as the new rest pose; if the
    /// connected body is destroyed the joint goes inert (Unity re-attaches it to the world).
    /// </summary>
    public abstract class Joint : Component
    {
        Rigidbody? _connected;
        Vector3 _anchor;
        Vector3 _connectedAnchor;
        bool _autoConfigure = true;
        Vector3 _axis = Vector3.UnitX;
        float _breakForce = float.PositiveInfinity;
        float _breakTorque = float.PositiveInfinity;
        bool _enableCollision;
        JointHandle _joint;
        Rigidbody? _own;

        /// <summary>The Core joint, or None while it is not built (inactive, or a body missing).</summary>
        public JointHandle joint => _joint;

        /// <summary>The other rigidbody, or null to attach to the world.</summary>
        public Rigidbody? connectedBody
        {
            get => _connected;
            set
            {
                ThrowIfStepping(nameof(connectedBody));
                if (value != null && value.isDestroyed)
                    throw new InvalidOperationException($"{this}: connectedBody ({value}) has been destroyed.");
                if (value != null && value.scene != scene)
                    throw new ArgumentException($"{this}: connectedBody ({value}) belongs to another scene.", nameof(connectedBody));
                if (value != null && value.entity == entity)
                    throw new ArgumentException($"{this}: connectedBody is the joint's own Rigidbody; a joint needs two bodies (or null for the world).", nameof(connectedBody));
                _connected = value;
                Rebuild();
            }
        }

        /// <summary>The joint point in this entity's frame, metres. Default: 0.</summary>
        public Vector3 anchor
        {
            get => _anchor;
            set { FieldCheck.Finite(value, this, nameof(anchor)); SetJointField(ref _anchor, value, nameof(anchor)); }
        }

        /// <summary>The joint point in the connected body's frame (a world point without one), metres.</summary>
        public Vector3 connectedAnchor
        {
            get => _connectedAnchor;
            set { FieldCheck.Finite(value, this, nameof(connectedAnchor)); ThrowIfStepping(nameof(connectedAnchor)); _connectedAnchor = value; _autoConfigure = false; Rebuild(); }
        }

        /// <summary>Compute <see cref="connectedAnchor"/> from <see cref="anchor"/> when the joint is built. Default: true.</summary>
        public bool autoConfigureConnectedAnchor
        {
            get => _autoConfigure;
            set => SetJointField(ref _autoConfigure, value, nameof(autoConfigureConnectedAnchor));
        }

        /// <summary>The joint axis in this entity's frame (hinge axis, twist axis). Default: +x.</summary>
        public Vector3 axis
        {
            get => _axis;
            set
            {
                FieldCheck.Finite(value, this, nameof(axis));
                if (!(value.LengthSquared() > 1e-12f)) throw new ArgumentException($"{this}: axis must be non-zero, got {value}.", nameof(axis));
                ThrowIfStepping(nameof(axis));
                _axis = Vector3.Normalize(value);
                Rebuild();
            }
        }

        /// <summary>Force above which the joint breaks, N (&gt; 0; infinity = never). Default: infinity.</summary>
        public float breakForce
        {
            get => _breakForce;
            set
            {
                SetBreakLimit(ref _breakForce, value, nameof(breakForce));
                if (!_joint.IsNone) scene.world.Joints.Data[_joint.Index].BreakForce = value;
            }
        }

        /// <summary>Torque above which the joint breaks, N m (&gt; 0; infinity = never). Default: infinity.</summary>
        public float breakTorque
        {
            get => _breakTorque;
            set
            {
                SetBreakLimit(ref _breakTorque, value, nameof(breakTorque));
                if (!_joint.IsNone) scene.world.Joints.Data[_joint.Index].BreakTorque = value;
            }
        }

        /// <summary>Whether the two bodies still collide with each other. Default: false.</summary>
        public bool enableCollision
        {
            get => _enableCollision;
            set => SetJointField(ref _enableCollision, value, nameof(enableCollision));
        }

        /// <summary>The force the joint applied to this body in the last step, world, N.</summary>
        public Vector3 currentForce => IsBuilt ? scene.world.GetJointForce(_joint) : Vector3.Zero;

        /// <summary>The torque the joint applied to this body in the last step, world, N m.</summary>
        public Vector3 currentTorque => IsBuilt ? scene.world.GetJointTorque(_joint) : Vector3.Zero;

        internal bool IsBuilt => !_joint.IsNone && scene.world.IsValid(_joint);

        /// <summary>Fills the kind-specific fields of the Core joint definition.</summary>
        internal abstract void Configure(ref JointDef def);

        internal override void OnAdded()
        {
            if (entity.GetComponent<Rigidbody>() == null)
                throw new InvalidOperationException($"{this} needs a Rigidbody on entity '{name}': add the Rigidbody first.");
        }

        internal override void Activate()
        {
            scene.RegisterJoint(this);
            TryBuild();
        }

        internal override void Deactivate() => Unbuild();

        internal override void Teardown()
        {
            Unbuild();
            scene.UnregisterJoint(this);
        }

        /// <summary>Builds the Core joint when both ends have bodies; called on activation and before each step.</summary>
        internal void TryBuild()
        {
            if (!_joint.IsNone)
            {
                if (scene.world.IsValid(_joint)) return;
                _joint = default; // a body it named went away
            }
            if (!IsLive) return;
            Rigidbody? own = entity.GetComponent<Rigidbody>();
            if (own == null || !own.HasBody) return;
            Rigidbody? other = _connected;
            if (other != null && (other.isDestroyed || !other.HasBody)) return;
            World w = scene.world;
            Pose self = w.GetBody(own.body).Pose;
            // A = the connected body (or the world), B = this body: Core reports angles and motor
            // speeds of B relative to A, which is Unity's "this relative to connected".
            Vector3 anchorWorld = self.TransformPoint(_anchor);
            Vector3 axisWorld = self.TransformDirection(_axis);
            JointDef def = JointDef.Default;
            def.BodyA = other?.body ?? BodyHandle.None;
            def.BodyB = own.body;
            def.AnchorB = _anchor;
            def.AxisB = _axis;
            if (other != null)
            {
                Pose o = w.GetBody(other.body).Pose;
                if (_autoConfigure) _connectedAnchor = o.InverseTransformPoint(anchorWorld);
                def.AnchorA = _connectedAnchor;
                def.AxisA = o.InverseTransformDirection(axisWorld);
            }
            else
            {
                if (_autoConfigure) _connectedAnchor = anchorWorld;
                def.AnchorA = _connectedAnchor;
                def.AxisA = axisWorld;
            }
            def.BreakForce = _breakForce;
            def.BreakTorque = _breakTorque;
            def.CollideConnected = _enableCollision;
            def.Name = ToString();
            Configure(ref def);
            _joint = w.CreateJoint(def);
            _own = own;
            scene.MapJoint(_joint, this);
        }

        void Unbuild()
        {
            if (!_joint.IsNone && scene.world.IsValid(_joint)) scene.world.DestroyJoint(_joint);
            _joint = default;
            _own = null;
        }

        // The head of the breakForce and breakTorque setters: check, refuse mid-step, store; the
        // caller then writes the value into the live joint.
        void SetBreakLimit(ref float field, float value, string member)
        {
            FieldCheck.BreakLimit(value, this, member);
            ThrowIfStepping(member);
            field = value;
        }

        /// <summary>
        /// The tail of every setter whose value the built joint bakes in (anchors, limits,
        /// springs): refuses the change while the world steps, stores <paramref name="value"/>
        /// and rebuilds the live joint. The caller validates the value first, so a bad value is
        /// reported as such even mid-step.
        /// </summary>
        internal void SetJointField<T>(ref T field, T value, string member)
        {
            ThrowIfStepping(member);
            field = value;
            Rebuild();
        }

        /// <summary>Rebuilds a built joint after a structural change (the current pose becomes the rest pose).</summary>
        internal void Rebuild()
        {
            if (_joint.IsNone) return;
            Unbuild();
            TryBuild();
        }
    }
}
