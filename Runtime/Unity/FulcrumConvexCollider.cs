#nullable enable
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>
    /// A convex hull collider: the hull of a Unity mesh's vertices (this GameObject's MeshFilter
    /// mesh when <see cref="sharedMesh"/> is empty), scaled by the lossyScale. Unity spells this
    /// MeshCollider with convex on; Fulcrum gives it its own component because a hull is what
    /// dynamic bodies of any shape use. The mesh must be readable (Read/Write enabled).
    /// </summary>
    public sealed class FulcrumConvexCollider : FulcrumCollider
    {
        [SerializeField, Tooltip("The mesh whose vertices' hull is the shape; empty = this GameObject's MeshFilter mesh.")] Mesh? m_Mesh;

        /// <summary>The mesh whose vertices' hull is the shape; null = this GameObject's MeshFilter mesh.</summary>
        public Mesh? sharedMesh { get => m_Mesh; set { m_Mesh = value; Push(); } }

        readonly MeshCache _cache = new MeshCache();

        /// <inheritdoc/>
        protected override F.Collider Create(F.Entity shadow) => shadow.AddComponent<F.MeshCollider>();

        /// <inheritdoc/>
        protected override void PushShape(F.Collider c) => UnityMeshes.Assign((F.MeshCollider)c, true, m_Mesh, this, _cache);
    }
}
