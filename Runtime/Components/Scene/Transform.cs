using System;
using System.Collections.Generic;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    /// <summary>
    /// Position and rotation of an <see cref="Entity"/>, relative to an optional parent, like
    /// Unity's Transform. Member names follow Unity's so that code ports by changing the
    /// using. Departures from Unity: there is no scale (give collider sizes directly), and
    /// the world pose is computed from the chain of parents on every read (hierarchies in a
    /// physics scene are shallow).
    /// </summary>
    public sealed class Transform
    {
        readonly Entity _entity;
        Vector3 _localPosition;
        Quaternion _localRotation = Quaternion.Identity;
        Transform? _parent;
        readonly List<Transform> _children = new List<Transform>();

        // Bumped by every edit from user code (not by the host writing physics poses back), so
        // the host can tell that a body must be teleported to where the user put it.
        long _version;

        internal Transform(Entity entity)
        {
            _entity = entity;
        }

        /// <summary>The entity this transform belongs to.</summary>
        public Entity entity => _entity;

        /// <summary>Position relative to the parent (world when there is none), metres.</summary>
        public Vector3 localPosition
        {
            get => _localPosition;
            set
            {
                FieldCheck.Finite(value, this, "localPosition");
                _localPosition = value;
                _version++;
            }
        }

        /// <summary>Rotation relative to the parent; normalised when set.</summary>
        public Quaternion localRotation
        {
            get => _localRotation;
            set
            {
                _localRotation = FieldCheck.Rotation(value, this, "localRotation");
                _version++;
            }
        }

        /// <summary>World position, metres.</summary>
        public Vector3 position
        {
            get => _parent == null ? _localPosition : _parent.TransformPoint(_localPosition);
            set
            {
                FieldCheck.Finite(value, this, "position");
                _localPosition = _parent == null ? value : _parent.InverseTransformPoint(value);
                _version++;
            }
        }

        /// <summary>World rotation; normalised when set.</summary>
        public Quaternion rotation
        {
            get => _parent == null ? _localRotation : Quaternion.Normalize(_parent.rotation * _localRotation);
            set
            {
                Quaternion q = FieldCheck.Rotation(value, this, "rotation");
                _localRotation = _parent == null ? q : Quaternion.Normalize(Quaternion.Conjugate(_parent.rotation) * q);
                _version++;
            }
        }

        /// <summary>Sets world position and rotation together.</summary>
        public void SetPositionAndRotation(Vector3 position, Quaternion rotation)
        {
            this.position = position;
            this.rotation = rotation;
        }

        /// <summary>The local +z axis in world space (Unity's forward).</summary>
        public Vector3 forward => Vector3.Transform(Vector3.UnitZ, rotation);

        /// <summary>The local +y axis in world space.</summary>
        public Vector3 up => Vector3.Transform(Vector3.UnitY, rotation);

        /// <summary>The local +x axis in world space.</summary>
        public Vector3 right => Vector3.Transform(Vector3.UnitX, rotation);

        /// <summary>The parent, or null. Setting it keeps the world pose (see <see cref="SetParent"/>).</summary>
        public Transform? parent
        {
            get => _parent;
            set => SetParent(value, true);
        }

        /// <summary>The topmost ancestor (this transform when it has no parent).</summary>
        public Transform root
        {
            get
            {
                Transform t = this;
                while (t._parent != null) t = t._parent;
                return t;
            }
        }

        /// <summary>Number of direct children.</summary>
        public int childCount => _children.Count;

        /// <summary>The direct child at <paramref name="index"/>, in the order they were parented.</summary>
        public Transform GetChild(int index) => _children[index];

        /// <summary>
        /// Re-parents this transform. With <paramref name="worldPositionStays"/> the world pose
        /// is kept (the local pose changes), otherwise the local pose is kept. Colliders below
        /// it re-attach to the nearest <see cref="Rigidbody"/> above them, as in Unity.
        /// </summary>
        public void SetParent(Transform? parent, bool worldPositionStays = true)
        {
            if (parent == _parent) return;
            if (parent != null)
            {
                if (parent._entity.scene != _entity.scene)
                    throw new ArgumentException($"Transform of '{_entity.name}': parent '{parent._entity.name}' belongs to another scene.", nameof(parent));
                for (Transform? t = parent; t != null; t = t._parent)
                    if (t == this) throw new ArgumentException($"Transform of '{_entity.name}': parent '{parent._entity.name}' is its own descendant; the hierarchy would become a loop.", nameof(parent));
            }
            Pose world = WorldPose;
            _parent?._children.Remove(this);
            _parent = parent;
            parent?._children.Add(this);
            if (worldPositionStays) SetWorldPoseSilently(world);
            _version++;
            _entity.OnHierarchyChanged();
        }

        /// <summary>Maps a point from this transform's frame to the world.</summary>
        public Vector3 TransformPoint(Vector3 local) => WorldPose.TransformPoint(local);

        /// <summary>Maps a world point into this transform's frame.</summary>
        public Vector3 InverseTransformPoint(Vector3 world) => WorldPose.InverseTransformPoint(world);

        /// <summary>Rotates a direction from this transform's frame to the world.</summary>
        public Vector3 TransformDirection(Vector3 local) => Vector3.Transform(local, rotation);

        /// <summary>Rotates a world direction into this transform's frame.</summary>
        public Vector3 InverseTransformDirection(Vector3 world) => Vector3.Transform(world, Quaternion.Conjugate(rotation));

        /// <summary>The world pose (position and rotation).</summary>
        internal Pose WorldPose
        {
            get
            {
                if (_parent == null) return new Pose(_localPosition, _localRotation);
                return _parent.WorldPose * new Pose(_localPosition, _localRotation);
            }
        }

        /// <summary>The pose relative to <paramref name="ancestor"/>'s frame (identity for itself).</summary>
        internal Pose PoseRelativeTo(Transform ancestor)
        {
            Pose p = Pose.Identity;
            for (Transform? t = this; t != null && t != ancestor; t = t._parent)
                p = new Pose(t._localPosition, t._localRotation) * p;
            return p;
        }

        /// <summary>
        /// Sets the world pose without counting it as a user edit: the host uses it to show a
        /// body's simulated (or interpolated) pose.
        /// </summary>
        internal void SetWorldPoseSilently(in Pose world)
        {
            if (_parent == null)
            {
                _localPosition = world.Position;
                _localRotation = world.Rotation;
                return;
            }
            Pose local = _parent.WorldPose.Inverse() * world;
            _localPosition = local.Position;
            _localRotation = local.Rotation;
        }

        /// <summary>
        /// Grows whenever this transform or an ancestor is edited by user code; equal values
        /// mean the world pose is still the one the host last saw.
        /// </summary>
        internal long HierarchyVersion => VersionBelow(null);

        /// <summary>Like <see cref="HierarchyVersion"/>, counting only the transforms below <paramref name="ancestor"/> (exclusive).</summary>
        internal long VersionBelow(Transform? ancestor)
        {
            long v = 0;
            for (Transform? t = this; t != null && t != ancestor; t = t._parent) v += t._version;
            return v;
        }

        internal void DetachFromParentForDestroy()
        {
            _parent?._children.Remove(this);
            _parent = null;
        }

        internal List<Transform> Children => _children;

        /// <summary>"Transform of 'entity'": how errors name it.</summary>
        public override string ToString() => $"Transform of '{_entity.name}'";
    }
}
