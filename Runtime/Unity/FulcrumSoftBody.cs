#nullable enable
using System;
using Fulcrum.SoftBodies;
using UnityEngine;
using F = Fulcrum.Components;
using N = System.Numerics;

namespace Fulcrum.Unity
{
    /// <summary>
    /// A Neo-Hookean soft body from this GameObject's mesh (Unity face of
    /// <see cref="F.SoftBody"/>): when enabled, the MeshFilter's mesh (scaled by the lossyScale)
    /// is tetrahedralised (<see cref="SurfaceTetrahedralizer"/>, <see cref="resolution"/> cells
    /// along its longest side), simulated in world space, and the render mesh, embedded in the
    /// tetrahedra by barycentric coordinates (<see cref="EmbeddedRenderMesh"/>), follows it:
    /// every LateUpdate the deformed vertices and normals are written into the MeshFilter's own
    /// mesh instance without allocating. The GameObject's transform stays where it was (the
    /// vertices move, in its local frame). The mesh must be closed and readable (Read/Write
    /// enabled). A soft body and a FulcrumRigidbody do not share a GameObject.
    /// </summary>
    [DisallowMultipleComponent]
    [RequireComponent(typeof(MeshFilter))]
    public sealed class FulcrumSoftBody : FulcrumComponent
    {
        [Tooltip("Cells of the tetrahedral grid along the mesh's longest side (2-256); cost grows with its cube.")]
        public int resolution = 6;
        [Tooltip("Young's modulus, Pa (jelly 1e4, rubber 1e6-1e7).")] public float youngsModulus = 1e5f;
        [Tooltip("Poisson ratio in [0, 0.5); near 0.5 is nearly incompressible.")] public float poissonRatio = 0.45f;
        [Tooltip("Density, kg/m^3.")] public float density = 1000f;
        [Tooltip("Coulomb friction against colliders.")] public float friction = 0.5f;
        [Tooltip("XPBD (fast, soft) or Newton (converges on stiff materials).")] public SoftSolver solver = SoftSolver.Xpbd;
        [Tooltip("Substeps per physics step; 0 = automatic.")] public int substeps;
        [Tooltip("Stiffness-proportional damping time, s: how quickly wobbles die.")] public float dampingTime = 0.01f;

        F.SoftBody? _body;
        EmbeddedRenderMesh? _embedding;
        Mesh? _renderMesh;
        N.Vector3[] _worldVertices = Array.Empty<N.Vector3>();
        N.Vector3[] _worldNormals = Array.Empty<N.Vector3>();
        Vector3[] _vertices = Array.Empty<Vector3>();
        Vector3[] _normals = Array.Empty<Vector3>();

        /// <summary>The headless soft body component (null while disabled).</summary>
        public F.SoftBody? Body => _body;

        /// <summary>The tetrahedral mesh made from the render mesh (null while disabled).</summary>
        public SoftMesh? TetMesh => _body?.mesh;

        void OnEnable()
        {
            MeshFilter filter = GetComponent<MeshFilter>();
            Mesh source = UnityMeshes.MeshOf(this, filter.sharedMesh);
            N.Vector3[] rest = UnityMeshes.ScaledVertices(source, transform.lossyScale, this);
            int[] triangles = source.triangles;
            SoftMesh tets;
            try { tets = SurfaceTetrahedralizer.Tetrahedralize(rest, triangles, resolution); }
            catch (ArgumentException e) { throw new ArgumentException($"{name}: FulcrumSoftBody cannot tetrahedralise mesh '{source.name}': {e.Message}", e); }
            _embedding = new EmbeddedRenderMesh(tets, rest, triangles);

            _body = Shadow.AddComponent<F.SoftBody>();
            Push(_body);
            _body.mesh = tets;

            // The MeshFilter's own instance: the shared asset is never written.
            _renderMesh = filter.mesh;
            _renderMesh.MarkDynamic();
            int n = _embedding.VertexCount;
            _worldVertices = new N.Vector3[n];
            _worldNormals = new N.Vector3[n];
            _vertices = new Vector3[n];
            _normals = new Vector3[n];
        }

        void Push(F.SoftBody b)
        {
            b.material = new NeoHookeanMaterial(MaterialModel.StableNeoHookean, youngsModulus, poissonRatio, density);
            b.friction = friction;
            b.solver = solver;
            b.substeps = substeps;
            b.dampingTime = dampingTime;
        }

        void OnValidate()
        {
            resolution = Mathf.Clamp(resolution, 2, 256);
            youngsModulus = Mathf.Max(youngsModulus, 1f);
            poissonRatio = Mathf.Clamp(poissonRatio, 0f, 0.4999f);
            density = Mathf.Max(density, 1e-3f);
            friction = Mathf.Max(friction, 0f);
            substeps = Mathf.Clamp(substeps, 0, 1000);
            dampingTime = Mathf.Max(dampingTime, 0f);
            // The material rebuilds the body at rest; the cheap settings are pushed live.
            if (IsLive && _body != null && !_body.isDestroyed)
            {
                _body.friction = friction;
                _body.solver = solver;
                _body.substeps = substeps;
                _body.dampingTime = dampingTime;
            }
        }

        // Once per rendered frame: the render mesh follows the tetrahedra (allocation-free).
        void LateUpdate()
        {
            Fulcrum.SoftBodies.SoftBody? b = _body?.body;
            if (b == null || _embedding == null || _renderMesh == null) return;
            _embedding.Update(b.Positions, _worldVertices, _worldNormals);
            Transform t = transform;
            for (int i = 0; i < _vertices.Length; i++)
            {
                _vertices[i] = t.InverseTransformPoint(_worldVertices[i].ToUnity());
                _normals[i] = t.InverseTransformDirection(_worldNormals[i].ToUnity());
            }
            _renderMesh.SetVertices(_vertices);
            _renderMesh.SetNormals(_normals);
            _renderMesh.RecalculateBounds();
        }

        void OnDisable()
        {
            if (_body != null && !_body.isDestroyed) _body.scene.DestroyImmediate(_body);
            _body = null;
            _embedding = null;
            ReleaseShadow();
        }
    }
}
