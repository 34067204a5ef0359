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
        [SerializeField, Tooltip("Cells of the tetrahedral grid along the mesh's longest side (2-256); cost grows with its cube.")]
        int m_Resolution = 6;
        [SerializeField, Tooltip("Young's modulus, Pa (jelly 1e4, rubber 1e6-1e7).")] float m_YoungsModulus = 1e5f;
        [SerializeField, Tooltip("Poisson ratio in [0, 0.5); near 0.5 is nearly incompressible.")] float m_PoissonRatio = 0.45f;
        [SerializeField, Tooltip("Density, kg/m^3.")] float m_Density = 1000f;
        [SerializeField, Tooltip("Coulomb friction against colliders.")] float m_Friction = 0.5f;
        [SerializeField, Tooltip("XPBD (fast, soft) or Newton (converges on stiff materials).")] SoftSolver m_Solver = SoftSolver.Xpbd;
        [SerializeField, Tooltip("Substeps per physics step; 0 = automatic.")] int m_Substeps;
        [SerializeField, Tooltip("Stiffness-proportional damping time, s: how quickly wobbles die.")] float m_DampingTime = 0.01f;

        /// <summary>Grid cells along the mesh's longest side (2-256); read when the component is enabled.</summary>
        public int resolution { get => m_Resolution; set => m_Resolution = value; }
        /// <summary>Young's modulus, Pa. Changing it rebuilds a live body at rest.</summary>
        public float youngsModulus { get => m_YoungsModulus; set { m_YoungsModulus = value; PushMaterial(); } }
        /// <summary>Poisson ratio in [0, 0.5). Changing it rebuilds a live body at rest.</summary>
        public float poissonRatio { get => m_PoissonRatio; set { m_PoissonRatio = value; PushMaterial(); } }
        /// <summary>Density, kg/m^3. Changing it rebuilds a live body at rest.</summary>
        public float density { get => m_Density; set { m_Density = value; PushMaterial(); } }
        /// <summary>Coulomb friction against colliders.</summary>
        public float friction { get => m_Friction; set { m_Friction = value; PushLive(); } }
        /// <summary>The elastic solver.</summary>
        public SoftSolver solver { get => m_Solver; set { m_Solver = value; PushLive(); } }
        /// <summary>Substeps per physics step; 0 = automatic.</summary>
        public int substeps { get => m_Substeps; set { m_Substeps = value; PushLive(); } }
        /// <summary>Stiffness-proportional damping time, s.</summary>
        public float dampingTime { get => m_DampingTime; set { m_DampingTime = value; PushLive(); } }

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
            Mesh source = UnityMeshes.MeshOf(this, null);
            N.Vector3[] rest = UnityMeshes.ScaledVertices(source, transform.lossyScale, this);
            int[] triangles = source.triangles;
            SoftMesh tets;
            try { tets = SurfaceTetrahedralizer.Tetrahedralize(rest, triangles, m_Resolution); }
            catch (ArgumentException e) { throw new ArgumentException($"{name}: FulcrumSoftBody cannot tetrahedralise mesh '{source.name}': {e.Message}", e); }
            _embedding = new EmbeddedRenderMesh(tets, rest, triangles);

            _body = Shadow.AddComponent<F.SoftBody>();
            Push(_body);
            _body.mesh = tets;

            // The MeshFilter's own instance: the shared asset is never written.
            _renderMesh = GetComponent<MeshFilter>().mesh;
            _renderMesh.MarkDynamic();
            int n = _embedding.VertexCount;
            _worldVertices = new N.Vector3[n];
            _worldNormals = new N.Vector3[n];
            _vertices = new Vector3[n];
            _normals = new Vector3[n];
        }

        void Push(F.SoftBody b)
        {
            b.material = Material();
            PushLive(b);
        }

        NeoHookeanMaterial Material() => new NeoHookeanMaterial(MaterialModel.StableNeoHookean, m_YoungsModulus, m_PoissonRatio, m_Density);

        void PushMaterial()
        {
            if (_body != null && !_body.isDestroyed) _body.material = Material();
        }

        void PushLive()
        {
            if (_body != null && !_body.isDestroyed) PushLive(_body);
        }

        void PushLive(F.SoftBody b)
        {
            b.friction = m_Friction;
            b.solver = m_Solver;
            b.substeps = m_Substeps;
            b.dampingTime = m_DampingTime;
        }

        void OnValidate()
        {
            m_Resolution = Mathf.Clamp(m_Resolution, 2, 256);
            m_YoungsModulus = Mathf.Max(m_YoungsModulus, 1f);
            m_PoissonRatio = Mathf.Clamp(m_PoissonRatio, 0f, 0.4999f);
            m_Density = Mathf.Max(m_Density, 1e-3f);
            m_Friction = Mathf.Max(m_Friction, 0f);
            m_Substeps = Mathf.Clamp(m_Substeps, 0, 1000);
            m_DampingTime = Mathf.Max(m_DampingTime, 0f);
            // The material would rebuild the body at rest: inspector edits push only the cheap settings.
            if (IsLive) PushLive();
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
