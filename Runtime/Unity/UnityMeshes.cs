#nullable enable
using System;
using UnityEngine;
using F = Fulcrum.Components;
using N = System.Numerics;

namespace Fulcrum.Unity
{
    /// <summary>Unity meshes as Fulcrum geometry, with the GameObject's scale baked in (Fulcrum's entities carry no scale).</summary>
    public static class UnityMeshes
    {
        /// <summary>
        /// The vertices of <paramref name="mesh"/> multiplied component-wise by
        /// <paramref name="scale"/> (the transform's lossyScale), as System.Numerics vectors.
        /// Throws when the mesh's data cannot be read (Read/Write disabled in its import settings).
        /// </summary>
        public static N.Vector3[] ScaledVertices(Mesh mesh, Vector3 scale, UnityEngine.Object owner)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh), $"{owner.name}: no mesh is assigned.");
            if (!mesh.isReadable)
                throw new InvalidOperationException($"{owner.name}: mesh '{mesh.name}' is not readable; enable Read/Write in its import settings so that Fulcrum can build its shape.");
            Vector3[] v = mesh.vertices;
            var result = new N.Vector3[v.Length];
            for (int i = 0; i < v.Length; i++) result[i] = new N.Vector3(v[i].x * scale.x, v[i].y * scale.y, v[i].z * scale.z);
            return result;
        }

        /// <summary><paramref name="assigned"/>, or else the mesh of the MeshFilter on <paramref name="owner"/>'s GameObject; throws when there is neither.</summary>
        public static Mesh MeshOf(Component owner, Mesh? assigned)
        {
            if (assigned != null) return assigned;
            MeshFilter filter = owner.GetComponent<MeshFilter>();
            Mesh? mesh = filter != null ? filter.sharedMesh : null;
            if (mesh == null) throw new InvalidOperationException($"{owner.name}: {owner.GetType().Name} has no mesh (assign one or add a MeshFilter with a mesh).");
            return mesh;
        }

        /// <summary>
        /// Gives <paramref name="collider"/> the mesh of <paramref name="owner"/> (its assigned one, or its
        /// MeshFilter's) at the owner's lossyScale, as a hull when <paramref name="convex"/>; the
        /// shape is rebuilt only when the mesh or the scale changed.
        /// </summary>
        internal static void Assign(F.MeshCollider collider, bool convex, Mesh? assigned, Component owner, MeshCache cache)
        {
            collider.convex = convex;
            F.Mesh built = cache.Get(MeshOf(owner, assigned), owner.transform.lossyScale, owner);
            if (!ReferenceEquals(collider.sharedMesh, built)) collider.sharedMesh = built;
        }

        /// <summary>A headless <see cref="F.Mesh"/> of <paramref name="mesh"/> at <paramref name="scale"/>.</summary>
        public static F.Mesh ToFulcrum(Mesh mesh, Vector3 scale, UnityEngine.Object owner) =>
            new F.Mesh(ScaledVertices(mesh, scale, owner), mesh.triangles) { name = mesh.name };
    }

    /// <summary>
    /// The headless mesh last built for a collider, rebuilt only when the Unity mesh or the scale
    /// changes (a hull costs a quickhull; a changed mesh instance rebuilds the shape).
    /// </summary>
    internal sealed class MeshCache
    {
        F.Mesh? _built;
        Mesh? _from;
        Vector3 _scale;

        /// <summary>The headless mesh for <paramref name="mesh"/> at <paramref name="scale"/>, the same instance while they do not change.</summary>
        public F.Mesh Get(Mesh mesh, Vector3 scale, UnityEngine.Object owner)
        {
            if (_built == null || !ReferenceEquals(_from, mesh) || !(_scale == scale))
            {
                _built = UnityMeshes.ToFulcrum(mesh, scale, owner);
                _from = mesh;
                _scale = scale;
            }
            return _built;
        }
    }
}
