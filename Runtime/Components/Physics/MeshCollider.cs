using System;

namespace Fulcrum.Components
{
    /// <summary>
    /// A collider from a <see cref="Mesh"/>: its convex hull when <see cref="convex"/> is set
    /// (for rigidbodies), else the triangle mesh itself (static colliders only, as in Unity;
    /// Fulcrum's triangles are one-sided: their front is where (b - a) x (c - a) points).
    /// </summary>
    public sealed class MeshCollider : Collider
    {
        Mesh? _mesh;
        bool _convex;

        /// <summary>The mesh. Required before the collider can go live.</summary>
        public Mesh? sharedMesh
        {
            get => _mesh;
            set
            {
                ThrowIfStepping(nameof(sharedMesh));
                if (value != null && IsLive && enabled)
                {
                    CheckBody(FindRigidbody());
                    MeshGeometry.Build(this, value, _convex);
                }
                _mesh = value;
                Remove();
                if (IsLive && enabled) Build();
            }
        }

        /// <summary>Use the mesh's convex hull (needed on a Rigidbody). Default: false.</summary>
        public bool convex
        {
            get => _convex;
            set
            {
                ThrowIfStepping(nameof(convex));
                if (value == _convex) return;
                if (!value && attachedRigidbody != null)
                    throw new InvalidOperationException($"{this}: convex = false needs a static collider, but it is part of the Rigidbody on '{attachedRigidbody.name}' (Fulcrum's triangle meshes are static only).");
                _convex = value;
                Rebuild();
            }
        }

        internal override bool HasGeometry => _mesh != null;

        internal override void CheckBody(Rigidbody? body)
        {
            if (!_convex && body != null)
                throw new InvalidOperationException($"{this}: convex = false needs a static collider, but the entity is part of the Rigidbody on '{body.name}'; set convex = true or remove the Rigidbody.");
        }

        internal override ShapeGeometry BuildGeometry()
        {
            if (_mesh == null) throw new InvalidOperationException($"{this}: sharedMesh is null; assign a Mesh first.");
            return MeshGeometry.Build(this, _mesh, _convex);
        }
    }
}
