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
        [Tooltip("The mesh; empty = this GameObject's MeshFilter mesh.")] public Mesh? sharedMesh;
        [Tooltip("Use the convex hull (required on a rigidbody).")] public bool convex;

        /// <inheritdoc/>
        protected override F.Collider Create(F.Entity shadow) => shadow.AddComponent<F.MeshCollider>();

        /// <inheritdoc/>
        protected override void PushShape(F.Collider c)
        {
            var m = (F.MeshCollider)c;
            m.convex = convex;
            m.sharedMesh = UnityMeshes.ToFulcrum(UnityMeshes.MeshOf(this, sharedMesh), transform.lossyScale, this);
        }
    }
}
