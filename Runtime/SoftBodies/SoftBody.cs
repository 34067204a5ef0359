using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// A deformable body of a <see cref="World"/>: a tet mesh (volume) or a triangle shell
    /// (cloth) with a Neo-Hookean material, stepped by XPBD in the world's soft-body stage.
    /// Get one with <see cref="SoftBodyWorldExtensions.GetSoftBody"/>. Vertex state is in
    /// world coordinates; elements are stored in solver (colour) order, and every per-element
    /// query below uses the mesh's own element order.
    /// </summary>
    public sealed partial class SoftBody
    {
        internal readonly World World;
        internal readonly int Slot;
        internal readonly int Generation;
        internal bool Destroyed;

        // Vertex state (world).
        internal readonly Vector3[] X;
        internal readonly Vector3[] XPrev;
        // Positions at the start of the step: where a diverged body is put back (SoftBodySystem).
        internal readonly Vector3[] XStart;
        // Velocities at the start of the step: with XStart, what a step taken again starts from (SoftBodySystem).
        internal readonly Vector3[] VStart;
        // The positions the substep's prediction gave (velocities come from the constraints' moves
        // away from them), and what that prediction's moves lost to rounding; see Substep.
        internal readonly Vector3[] XPredicted;
        internal readonly Vector3[] XResidual;
        internal readonly Vector3[] V;
        internal readonly float[] W;
        internal readonly float[] M;
        // W, and also 0 at vertices attached to rigid bodies: the torque-free projection skips
        // elements with such a vertex, whose impulses are shared with a body.
        internal readonly float[] FreeW;

        // Elements in colour order; *Colors[c] .. *Colors[c + 1] is colour c.
        internal readonly TetElement[] Tets;
        internal readonly int[] TetColors;
        internal readonly Vector2[] TetLambda;
        // Carries the kept gradients in saved states only; the solver keeps them in TetData.
        internal readonly TetGradients[] TetGrad;
        // The tets as the solver streams them (structure of arrays, same order as Tets).
        internal readonly TetStream TetData;
        internal readonly int[] TetOfMeshTet;
        internal readonly float[] PlasticStrain;
        internal readonly TriangleElement[] Tris;
        internal readonly int[] TriColors;
        internal readonly Vector2[] TriLambda;
        internal readonly int[] TriOfMeshTri;
        internal readonly BendElement[] Bends;
        internal readonly int[] BendColors;
        internal readonly float[] BendLambda;
        internal readonly Attachment[] Attachments;
        internal readonly ProbeBinding[] Probes;

        internal readonly StableNeoHookeanEnergy StableModel;
        internal readonly NeoHookeanEnergy ClassicModel;
        internal readonly MembraneEnergy MembraneModel;
        internal readonly float RestMeasure;      // total rest volume, or rest area for a shell
        internal readonly ShapeContactSolver Contacts = new ShapeContactSolver();
        internal readonly SelfCollision? SelfContacts;
        readonly float[] _scratch;                 // per-vertex scratch for colour queries

        internal SoftBody(World world, int slot, int generation, in SoftBodyDef def)
        {
            SoftMesh mesh = def.Mesh!;
            World = world;
            Slot = slot;
            Generation = generation;
            Name = def.Name;
            Mesh = mesh;
            Material = def.Material;
            Substeps = def.Substeps;
            Iterations = def.Iterations;
            DampingTime = def.DampingTime;
            LinearDamping = def.LinearDamping;
            GravityScale = def.GravityScale;
            Friction = def.Friction;
            CollisionRadius = def.CollisionRadius;
            CollideWithShapes = def.CollideWithShapes;
            CollideWithSoftBodies = def.CollideWithSoftBodies;
            Layer = def.Layer;
            CollidesWith = def.CollidesWith;
            Plasticity = def.Plasticity;
            Thickness = def.Thickness;
            _solver = def.Solver;

            Vector3[] rest = mesh.VertexArray;
            int n = rest.Length;
            X = new Vector3[n];
            XPrev = new Vector3[n];
            XStart = new Vector3[n];
            VStart = new Vector3[n];
            XPredicted = new Vector3[n];
            XResidual = new Vector3[n];
            V = new Vector3[n];
            W = new float[n];
            M = new float[n];
            FreeW = new float[n];
            _scratch = new float[2 * n];

            Quaternion rotation = Mathematics.Validate.Rotation(def.Rotation, "softBody.Rotation");
            Vector3 center = mesh.Center;
            for (int i = 0; i < n; i++)
            {
                X[i] = def.Position + Vector3.Transform(center + def.InitialDeformation * (rest[i] - center), rotation);
                XPrev[i] = X[i];
                V[i] = def.LinearVelocity;
            }

            StableModel = StableNeoHookeanEnergy.Of(def.Material);
            ClassicModel = def.Material.Model == MaterialModel.NeoHookean ? NeoHookeanEnergy.Of(def.Material) : default;
            MembraneModel = new MembraneEnergy(def.Material);
            float density = def.Material.Density;

            int[] meshTets = mesh.TetArray;
            int[] order = ElementColoring.Color(meshTets, 4, n, out TetColors);
            Tets = new TetElement[order.Length];
            TetOfMeshTet = new int[order.Length];
            TetLambda = new Vector2[order.Length];
            TetGrad = new TetGradients[order.Length];
            PlasticStrain = new float[order.Length];
            for (int k = 0; k < order.Length; k++)
            {
                int t = 4 * order[k];
                int a = meshTets[t], b = meshTets[t + 1], c = meshTets[t + 2], d = meshTets[t + 3];
                var dm = new Mat3(rest[b] - rest[a], rest[c] - rest[a], rest[d] - rest[a]);
                float volume = dm.Determinant / 6f;
                Tets[k] = new TetElement { A = a, B = b, C = c, D = d, RestInverse = dm.Inverse(), RestVolume = volume };
                TetOfMeshTet[order[k]] = k;
                float share = 0.25f * density * volume;
                M[a] += share; M[b] += share; M[c] += share; M[d] += share;
                RestMeasure += volume;
            }

            TetData = new TetStream(Tets.Length, n);
            TetData.LoadElements(Tets);

            int[] meshTris = mesh.TriangleArray;
            if (meshTris.Length > 0)
            {
                TriangleElement[] built = ShellBuilder.Triangles(rest, meshTris);
                int[] triOrder = ElementColoring.Color(meshTris, 3, n, out TriColors);
                Tris = new TriangleElement[built.Length];
                TriOfMeshTri = new int[built.Length];
                for (int k = 0; k < triOrder.Length; k++)
                {
                    Tris[k] = built[triOrder[k]];
                    TriOfMeshTri[triOrder[k]] = k;
                    float share = density * def.Thickness * Tris[k].RestArea / 3f;
                    M[Tris[k].A] += share; M[Tris[k].B] += share; M[Tris[k].C] += share;
                    RestMeasure += Tris[k].RestArea;
                }
                TriLambda = new Vector2[Tris.Length];
                float rigidity = ShellBuilder.Rigidity(def.Material, def.Thickness) * def.BendingScale;
                BendElement[] bends = rigidity > 0 ? ShellBuilder.Bends(rest, meshTris, rigidity) : Array.Empty<BendElement>();
                var bendIndices = new int[4 * bends.Length];
                for (int k = 0; k < bends.Length; k++)
                {
                    bendIndices[4 * k] = bends[k].A; bendIndices[4 * k + 1] = bends[k].B;
                    bendIndices[4 * k + 2] = bends[k].C; bendIndices[4 * k + 3] = bends[k].D;
                }
                int[] bendOrder = ElementColoring.Color(bendIndices, 4, n, out BendColors);
                Bends = new BendElement[bends.Length];
                for (int k = 0; k < bendOrder.Length; k++) Bends[k] = bends[bendOrder[k]];
                BendLambda = new float[Bends.Length];
            }
            else
            {
                Tris = Array.Empty<TriangleElement>();
                TriColors = new int[1];
                TriLambda = Array.Empty<Vector2>();
                TriOfMeshTri = Array.Empty<int>();
                Bends = Array.Empty<BendElement>();
                BendColors = new int[1];
                BendLambda = Array.Empty<float>();
            }

            for (int i = 0; i < n; i++)
            {
                TotalMass += M[i];
                W[i] = 1f / M[i];
            }

            // Pins: world pins zero the inverse mass; body pins become attachments.
            var attachments = new System.Collections.Generic.List<Attachment>();
            if (def.Pins != null)
            {
                for (int p = 0; p < def.Pins.Length; p++)
                {
                    SoftPin pin = def.Pins[p];
                    bool toBody = !pin.Body.IsNone;
                    int bodySlot = toBody ? world.Slot(pin.Body) : -1;
                    for (int i = 0; i < n; i++)
                    {
                        if (!SoftBodyDef.PinContains(mesh, pin.Min, pin.Max, rest[i])) continue;
                        if (!toBody)
                        {
                            W[i] = 0f;
                            V[i] = Vector3.Zero;
                            continue;
                        }
                        var bodyPose = new Pose(world.Bodies.Position[bodySlot], world.Bodies.Rotation[bodySlot]);
                        attachments.Add(new Attachment
                        {
                            Vertex = i,
                            BodySlot = bodySlot,
                            BodyGeneration = pin.Body.Generation,
                            LocalAnchor = bodyPose.InverseTransformPoint(X[i]),
                        });
                    }
                }
            }
            Attachments = attachments.ToArray();
            Array.Copy(W, FreeW, n);
            for (int k = 0; k < Attachments.Length; k++) FreeW[Attachments[k].Vertex] = 0f;
            Probes = ProbeBinder.Bind(mesh, def.Probes);
            if (def.SelfCollision) SelfContacts = new SelfCollision(mesh, def.CollisionRadius);
            if (_solver == SoftSolver.Newton) NewtonSolver = new ImplicitNewtonSolver(this);
        }

        /// <summary>The handle of this body.</summary>
        public SoftBodyHandle Handle => new SoftBodyHandle(Slot, Generation, World.Id);

        /// <summary>True once the body was removed from its world.</summary>
        public bool IsDestroyed => Destroyed;

        /// <summary>The name given in the def.</summary>
        public string? Name { get; }

        /// <summary>The rest mesh.</summary>
        public SoftMesh Mesh { get; }

        /// <summary>The material.</summary>
        public NeoHookeanMaterial Material { get; }

        /// <summary>True for a triangle shell.</summary>
        public bool IsShell => Tets.Length == 0;

        /// <summary>Number of vertices.</summary>
        public int VertexCount => X.Length;

        /// <summary>Total mass, kg.</summary>
        public float TotalMass { get; }

        /// <summary>Vertex positions, world, metres.</summary>
        public ReadOnlySpan<Vector3> Positions => X;

        /// <summary>Vertex velocities, m/s.</summary>
        public ReadOnlySpan<Vector3> Velocities => V;

        /// <summary>Vertex masses, kg (pinned vertices keep theirs here).</summary>
        public ReadOnlySpan<float> Masses => M;

        /// <summary>Vertex inverse masses, 1/kg (0 for pinned vertices).</summary>
        public ReadOnlySpan<float> InverseMasses => W;

        /// <summary>Number of probes.</summary>
        public int ProbeCount => Probes.Length;

        /// <summary>XPBD substeps per world step (0: automatic, see <see cref="SoftBodyDef.Substeps"/>).</summary>
        public int Substeps { get; set; }

        /// <summary>Constraint iterations per substep (&gt;= 1).</summary>
        public int Iterations { get; set; }

        /// <summary>Stiffness-proportional damping time, seconds.</summary>
        public float DampingTime { get; set; }

        /// <summary>Velocity damping, 1/s.</summary>
        public float LinearDamping { get; set; }

        /// <summary>Multiplies world gravity.</summary>
        public float GravityScale { get; set; }

        /// <summary>Friction against rigid shapes.</summary>
        public float Friction { get; set; }

        /// <summary>Distance vertices keep from shapes, metres.</summary>
        public float CollisionRadius { get; }

        /// <summary>Collide with rigid shapes.</summary>
        public bool CollideWithShapes { get; set; }

        /// <summary>Collide with other soft bodies (both must have it and pass each other's layer masks); see <see cref="SoftBodyDef.CollideWithSoftBodies"/>.</summary>
        public bool CollideWithSoftBodies { get; set; }

        /// <summary>Collision layer (0..31).</summary>
        public int Layer { get; }

        /// <summary>Shape layers this body collides with.</summary>
        public uint CollidesWith { get; }

        /// <summary>
        /// The elastic solver (<see cref="SoftSolver"/>); may be switched between steps. Newton
        /// needs tets: setting it on a shell throws <see cref="InvalidOperationException"/>.
        /// </summary>
        public SoftSolver Solver
        {
            get => _solver;
            set
            {
                ThrowIfStepping();
                if (value == SoftSolver.Newton && Tets.Length == 0)
                    throw new InvalidOperationException("SoftSolver.Newton solves tetrahedra; this body is a shell (use SoftSolver.Xpbd).");
                if (value != SoftSolver.Xpbd && value != SoftSolver.Newton) throw new ArgumentOutOfRangeException(nameof(value), $"unknown solver {value}.");
                _solver = value;
                if (value == SoftSolver.Newton && NewtonSolver == null) NewtonSolver = new ImplicitNewtonSolver(this);
            }
        }

        SoftSolver _solver;

        /// <summary>The Newton solver's band system, built when the solver is first Newton.</summary>
        internal ImplicitNewtonSolver? NewtonSolver;

        /// <summary>This step's contact pairs with other soft bodies (null when this body is in none), set before the substeps.</summary>
        internal SoftSoftContacts? SoftPairs;

        /// <summary>Substeps begun in the current step: a body whose count is not below another's has stepped the substep that one is in.</summary>
        internal int SubstepsBegun;

        /// <summary>Plastic flow settings.</summary>
        public SoftPlasticity Plasticity { get; set; }

        /// <summary>Shell thickness, metres.</summary>
        public float Thickness { get; }

        /// <summary>
        /// The substeps used for a step of <paramref name="dt"/>: <see cref="Substeps"/>, or one per
        /// 1/600 s; a <see cref="SoftSolver.Newton"/> body that touches nothing this step (no shape
        /// within reach, no attachment) takes one (implicit Euler is stable at the whole step).
        /// </summary>
        public int SubstepsFor(float dt) =>
            Substeps > 0 ? Substeps
            : _solver == SoftSolver.Newton && !Touching ? 1
            : Math.Max(1, Math.Min(64, (int)MathF.Ceiling(dt * 600f - 1e-3f)));

        /// <summary>True when this step's gather found shapes or other soft bodies within reach, or the body has attachments.</summary>
        internal bool Touching => Attachments.Length > 0 || SoftPairs != null || (CollideWithShapes && (Contacts.CandidateCount > 0 || Contacts.MeshPairCount > 0));

        /// <summary>The world position of probe <paramref name="index"/> (barycentric in its rest element).</summary>
        public Vector3 GetProbe(int index)
        {
            if ((uint)index >= (uint)Probes.Length) throw new ArgumentOutOfRangeException(nameof(index), $"probe {index} does not exist; the body has {Probes.Length}.");
            ProbeBinding p = Probes[index];
            Vector3 pos = p.Weights.X * X[p.A] + p.Weights.Y * X[p.B] + p.Weights.Z * X[p.C];
            if (p.D >= 0) pos += p.Weights.W * X[p.D];
            return pos;
        }

        /// <summary>Elements: tets, or triangles for a shell (the length per-element queries need).</summary>
        public int ElementCount => Tets.Length > 0 ? Tets.Length : Tris.Length;

        /// <summary>Centroid, volume ratio, min J, energies: the soft trace's data for the current state.</summary>
        public SoftBodyStats ComputeStats() => SoftBodyMeasures.Stats(this);

        /// <summary>Writes J = det F of every element (area ratio for a shell) in mesh element order.</summary>
        public void ComputeElementJ(Span<float> into) => SoftBodyMeasures.ElementJ(this, into);

        /// <summary>Writes the strain energy of every element, J, in mesh element order.</summary>
        public void ComputeElementEnergy(Span<float> into) => SoftBodyMeasures.ElementEnergy(this, into);

        /// <summary>Writes the elastic force on every vertex, N (minus the gradient of the strain energy; tets only).</summary>
        public void ComputeElasticForces(Span<Vector3> into) => SoftBodyMeasures.ElasticForces(this, into);

        /// <summary>
        /// Writes a debug colour (RGB in [0, 1]) per vertex from the strain of its elements:
        /// blue unstrained, green at half <paramref name="fullScaleStrain"/>, red at it and beyond.
        /// Allocates nothing.
        /// </summary>
        public void ComputeStrainColors(Span<Vector3> into, float fullScaleStrain = 0.2f)
        {
            Mathematics.Validate.Positive(fullScaleStrain, nameof(fullScaleStrain));
            SoftBodyMeasures.StrainColors(this, into, fullScaleStrain, _scratch);
        }

        /// <summary>Moves one vertex (and its start-of-substep copy), metres. Not during a step.</summary>
        public void SetVertexPosition(int vertex, Vector3 position)
        {
            CheckVertex(vertex);
            Mathematics.Validate.Finite(position, "position");
            ThrowIfStepping();
            X[vertex] = position;
            XPrev[vertex] = position;
            PositionsChanged();
        }

        /// <summary>Sets one vertex's velocity, m/s (ignored for pinned vertices). Not during a step.</summary>
        public void SetVertexVelocity(int vertex, Vector3 velocity)
        {
            CheckVertex(vertex);
            Mathematics.Validate.Finite(velocity, "velocity");
            ThrowIfStepping();
            if (W[vertex] > 0) V[vertex] = velocity;
        }

        /// <summary>Pins (inverse mass 0, velocity 0) or frees a vertex. Not during a step.</summary>
        public void SetVertexPinned(int vertex, bool pinned)
        {
            CheckVertex(vertex);
            ThrowIfStepping();
            W[vertex] = pinned ? 0f : 1f / M[vertex];
            FreeW[vertex] = IsAttached(vertex) ? 0f : W[vertex];
            if (pinned) V[vertex] = Vector3.Zero;
        }

        bool IsAttached(int vertex)
        {
            for (int k = 0; k < Attachments.Length; k++) if (Attachments[k].Vertex == vertex) return true;
            return false;
        }

        void CheckVertex(int vertex)
        {
            if ((uint)vertex >= (uint)X.Length) throw new ArgumentOutOfRangeException(nameof(vertex), $"vertex {vertex} does not exist; the body has {X.Length}.");
            if (Destroyed) throw new StaleHandleException($"{Handle} was destroyed.");
        }

        void ThrowIfStepping()
        {
            if (World.IsStepping) throw new InvalidOperationException("A soft body cannot be changed during Step (from a callback).");
        }
    }
}
