#nullable enable
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>
    /// Unity face of <see cref="F.MeshCollider"/>: a Unity mesh (this GameObject's MeshFilter's
    /// when <see cref="sharedMesh"/> is empty), scaled by the transform's lossyScale when enabled.
    /// Non-convex meshes are static only (as in Unity); set <see cref="convex"/> for a rigidbody.
    /// The mesh must be readable (Read/Write enabled).
    /// </summary>
    public sealed class FulcrumMeshCollider : FulcrumCollider
    {
        [SerializeField, Tooltip("The mesh; empty = this GameObject's MeshFilter mesh.")] Mesh? m_Mesh;
        [SerializeField, Tooltip("Use the convex hull (required on a rigidbody).")] bool m_Convex;

        /// <summary>The mesh; null = this GameObject's MeshFilter mesh.</summary>
        public Mesh? sharedMesh { get => m_Mesh; set { m_Mesh = value; Push(); } }

        /// <summary>Use the mesh's convex hull (required on a rigidbody).</summary>
        public bool convex { get => m_Convex; set { m_Convex = value; Push(); } }

        readonly MeshCache _cache = new MeshCache();

        /// <inheritdoc/>
        protected override F.Collider Create(F.Entity shadow) => shadow.AddComponent<F.MeshCollider>();

        /// <inheritdoc/>
        protected override void PushShape(F.Collider c) => UnityMeshes.Assign((F.MeshCollider)c, m_Convex, m_Mesh, this, _cache);
    }
}
