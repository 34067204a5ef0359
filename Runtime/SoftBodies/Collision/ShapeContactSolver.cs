using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Vertex-versus-rigid-shape contacts of one soft body. Once per step the shapes whose
    /// bounds (swept over the step) come near the body's are gathered; each iteration of each
    /// substep (before the elastic pass) every free vertex is pushed out of each of them to <see cref="SoftBody.CollisionRadius"/> as a
    /// zero-compliance XPBD constraint shared with the shape's body through its generalised
    /// inverse mass, then Coulomb friction removes the relative tangential displacement of the
    /// substep up to mu times the normal correction (Mueller et al. 2020, "Detailed Rigid Body
    /// Simulation with Extended Position Based Dynamics", section 3.5). Friction runs once more
    /// after the elastic pass, on the substep's whole slip, within what is left of the cone.
    /// Every shape kind takes part: spheres, boxes, capsules, planes and convex hulls through
    /// <see cref="ShapeDistance"/>; static triangle meshes one triangle at a time through
    /// <see cref="MeshVertexContacts"/>. A body with several shapes (a compound) meets each of
    /// them in turn. After a shape's vertex contacts, its corners and edges meet the surface
    /// triangles of a tet body (<see cref="ShapeFeatureContacts"/>), which its vertices alone let
    /// pass between them.
    /// </summary>
    internal sealed class ShapeContactSolver
    {
        int[] _shapes = Array.Empty<int>();
        // Per gathered shape: its bounds swept over the step, and how far its surface may move in it.
        Aabb[] _swept = Array.Empty<Aabb>();
        float[] _travel = Array.Empty<float>();
        int _count;
        // How far a vertex may come this step (radius, its speed, gravity): see HeaviestBody.
        float _reach;
        readonly MeshVertexContacts _meshes = new MeshVertexContacts();
        // Per vertex over the current substep: normal corrections (Lagrange multipliers, kg m)
        // and the friction spent against them, so the cone bounds the whole substep.
        float[] _pushed = Array.Empty<float>();
        float[] _held = Array.Empty<float>();
        // Per vertex over the current substep: the normal impulse (kg m) a Newton step's ground
        // springs carried, for the friction cone (see Support).
        float[] _support = Array.Empty<float>();
        bool _supportReplaced;
        // Per vertex over the current substep, Newton bodies only: the part of friction's move
        // handed to the velocity at the substep's end instead of the position (see Solve).
        Vector3[] _frictionMove = Array.Empty<Vector3>();
        // One immovable shape's patch of Newton vertices in a pass (see HoldPatch): vertex, slip
        // direction, contact point, and the correction that holds the whole slip.
        int[] _patchVertex = Array.Empty<int>();
        Vector3[] _patchTangent = Array.Empty<Vector3>(), _patchContact = Array.Empty<Vector3>(), _patchNormal = Array.Empty<Vector3>();
        float[] _patchSlip = Array.Empty<float>();
        // Per vertex: whether static friction held its whole slip against a shape in this
        // substep, and in the last one (a resting contact; see Solve).
        bool[] _stuckNow = Array.Empty<bool>(), _stuckLast = Array.Empty<bool>();
        // Per vertex: the normal of its last push by an immovable shape (static or kinematic),
        // and whether that happened in this substep or the last (the Newton solver holds such
        // vertices along the normal, see ImplicitNewtonSolver).
        Vector3[] _normal = Array.Empty<Vector3>();
        bool[] _holdNow = Array.Empty<bool>(), _holdLast = Array.Empty<bool>();
        // Per vertex: 1 + the slot of the dynamic body the Newton solver's step met it against
        // in this substep (0: none); see MetByNewton.
        int[] _newtonOwner = Array.Empty<int>();
        // Per vertex: whether it was within reach of an immovable shape while its body was at rest
        // (HoldPatch), in this substep and in the last, with the shape's normal and the velocity
        // of its surface there: the Newton step holds such a vertex across the normal (Sticks).
        bool[] _restNow = Array.Empty<bool>(), _restLast = Array.Empty<bool>();
        Vector3[] _restVelocityNow = Array.Empty<Vector3>(), _restVelocityLast = Array.Empty<Vector3>();
        Vector3[] _restNormalNow = Array.Empty<Vector3>(), _restNormalLast = Array.Empty<Vector3>();
        // Per vertex over the current substep: the friction impulse (kg m, along the way it pulled)
        // that the Newton step's sticking spring carried (see Stuck).
        Vector3[] _stick = Array.Empty<Vector3>();
        // Per vertex over the current substep: the part of the cone the sticking springs spent (CapSticks).
        float[] _stickHeld = Array.Empty<float>();

        // The body's outward-wound surface triangles (ShapeFeatureContacts), copied once, with
        // each one's tet: its fourth vertex and six times its rest volume.
        int[]? _surface;
        int[] _apex = Array.Empty<int>();
        float[] _restVolume6 = Array.Empty<float>();

        void Surface(SoftMesh mesh)
        {
            _surface = mesh.SurfaceTriangles.ToArray();
            _apex = mesh.SurfaceApexes.ToArray();
            _restVolume6 = new float[_apex.Length];
            ReadOnlySpan<Vector3> rest = mesh.Vertices;
            for (int t = 0; t < _apex.Length; t++)
            {
                Vector3 a = rest[_surface[3 * t]];
                _restVolume6[t] = -Vector3.Dot(Vector3.Cross(rest[_surface[3 * t + 1]] - a, rest[_surface[3 * t + 2]] - a), rest[_apex[t]] - a);
            }
        }

        // Per surface triangle over the current substep: the features' normal corrections and
        // the friction spent against them (as _pushed and _held for vertices).
        float[] _trianglePushed = Array.Empty<float>(), _triangleHeld = Array.Empty<float>();
        // Per vertex: whether a shape's feature met a surface triangle of it in this substep, and
        // in the last (a feature meets only a point that came in through the triangle or one next
        // to it; see ShapeFeatureContacts).
        bool[] _featureMetNow = Array.Empty<bool>(), _featureMetLast = Array.Empty<bool>();

        /// <summary>Vertex-triangle pairs gathered against triangle meshes for this step.</summary>
        public int MeshPairCount => _meshes.Count;

        /// <summary>Shapes gathered for this step.</summary>
        public int CandidateCount => _count;

        /// <summary>Finds the shapes this body may touch during a step of <paramref name="dt"/>; tracks their bodies in <paramref name="coupling"/>.</summary>
        public void Gather(World world, SoftBody body, float dt, RigidCoupling coupling)
        {
            _count = 0;
            if (body.Tets.Length > 0 && _surface == null) Surface(body.Mesh);
            _meshes.Clear();
            Vector3[] x = body.X, v = body.V;
            Aabb bounds = Aabb.Empty;
            float maxSpeed2 = 0;
            for (int i = 0; i < x.Length; i++)
            {
                bounds = Aabb.Union(bounds, x[i]);
                maxSpeed2 = MathF.Max(maxSpeed2, v[i].LengthSquared());
            }
            float gravity = (world.Gravity * body.GravityScale).Length();
            _reach = body.CollisionRadius + MathF.Sqrt(maxSpeed2) * dt + gravity * dt * dt + 0.01f;
            bounds = bounds.Expanded(_reach);

            ShapeStorage s = world.Shapes;
            BodyStorage b = world.Bodies;
            for (int k = 0; k < s.ActiveCount; k++)
            {
                int shape = s.Active[k];
                if (s.IsSensor[shape]) continue;
                if ((s.CollidesWith[shape] & (1u << body.Layer)) == 0 || (body.CollidesWith & (1u << s.Layer[shape])) == 0) continue;
                int owner = s.Body[shape];
                Aabb box;
                float travel = 0f;
                if (b.Type[owner] == BodyType.Static) box = s.WorldAabb[shape];
                else
                {
                    Aabb end = s.Geometry[shape].ComputeAabb(world.ShapeWorldPose(shape));
                    Pose start = new Pose(b.PreviousPosition[owner], b.PreviousRotation[owner]) * s.LocalPose[shape];
                    Aabb from = s.Geometry[shape].ComputeAabb(start);
                    box = Aabb.Union(end, from);
                    // How far the shape's surface may move in the step: its bounds' centre and size.
                    travel = Vector3.Distance(end.Center, from.Center) + (end.Extents - from.Extents).Length();
                }
                if (!box.Overlaps(bounds)) continue;
                if (s.Geometry[shape].Type == ShapeType.TriangleMesh)
                {
                    _meshes.Gather(world, shape, body, dt, gravity);
                    continue;
                }
                if (_count == _shapes.Length)
                {
                    Array.Resize(ref _shapes, Math.Max(8, 2 * _count));
                    Array.Resize(ref _swept, _shapes.Length);
                    Array.Resize(ref _travel, _shapes.Length);
                }
                _swept[_count] = box;
                _travel[_count] = travel;
                _shapes[_count++] = shape;
                coupling.Track(owner);
            }
        }

        /// <summary>
        /// The largest mass of a dynamic body among the gathered shapes' owners that rests on
        /// this body in this step, kg (0 for none): some vertex may come within reach of the
        /// shape's underside (its outward normal there within 60 degrees of
        /// <paramref name="down"/>; with no gravity, any side). Only such a body needs the
        /// soft body to carry its weight, which is what the inertia scaling this feeds is for
        /// (<see cref="SoftBody.InertiaRatio"/>); and that scaling also divides gravity, so a
        /// soft body scaled for a heavy body that merely touches it floats: a slab standing on
        /// its edge against a 1 t crate's side climbed it to 2.5 m and blew apart.
        /// </summary>
        public float HeaviestBody(World world, Vector3[] x, Vector3 down)
        {
            float heaviest = 0;
            BodyStorage b = world.Bodies;
            ShapeStorage s = world.Shapes;
            for (int k = 0; k < _count; k++)
            {
                int shape = _shapes[k];
                int owner = s.Body[shape];
                if (!RigidCoupling.Movable(b, owner) || b.Mass[owner] <= heaviest) continue;
                Aabb near = _swept[k].Expanded(_reach);
                // The body is at its start-of-step pose here (RigidCoupling.Track put it back).
                Pose pose = world.ShapeWorldPose(shape);
                ShapeGeometry geometry = s.Geometry[shape];
                float radius = _reach + _travel[k];
                for (int i = 0; i < x.Length; i++)
                {
                    if (!near.Contains(x[i])) continue;
                    if (down != Vector3.Zero && !(ShapeDistance.Query(geometry, pose, x[i], radius, out _, out Vector3 n) && Vector3.Dot(n, down) > 0.5f)) continue;
                    heaviest = b.Mass[owner];
                    break;
                }
            }
            return heaviest;
        }

        // What the last step left for this one (the arrays WriteState writes), kept at the step's
        // start so that a step taken again (SoftBodySystem) starts from it.
        bool[] _keptHold = Array.Empty<bool>(), _keptStuck = Array.Empty<bool>(), _keptRest = Array.Empty<bool>(), _keptFeatureMet = Array.Empty<bool>();
        Vector3[] _keptNormal = Array.Empty<Vector3>(), _keptRestNormal = Array.Empty<Vector3>(), _keptRestVelocity = Array.Empty<Vector3>();

        /// <summary>Keeps what the last step left for this one (see <see cref="BackToStepStart"/>).</summary>
        internal void KeepStepStart()
        {
            Keep(_holdNow, ref _keptHold);
            Keep(_stuckNow, ref _keptStuck);
            Keep(_restNow, ref _keptRest);
            Keep(_featureMetNow, ref _keptFeatureMet);
            Keep(_normal, ref _keptNormal);
            Keep(_restNormalNow, ref _keptRestNormal);
            Keep(_restVelocityNow, ref _keptRestVelocity);
        }

        /// <summary>
        /// Puts back what <see cref="KeepStepStart"/> kept, as a restored state does (the last
        /// substep's flags cleared): the step is taken again from its start.
        /// </summary>
        internal void BackToStepStart()
        {
            Back(_keptHold, _holdNow, _holdLast);
            Back(_keptStuck, _stuckNow, _stuckLast);
            Back(_keptRest, _restNow, _restLast);
            Back(_keptFeatureMet, _featureMetNow, _featureMetLast);
            Back(_keptNormal, _normal, null);
            Back(_keptRestNormal, _restNormalNow, _restNormalLast);
            Back(_keptRestVelocity, _restVelocityNow, _restVelocityLast);
        }

        static void Keep<T>(T[] now, ref T[] kept)
        {
            if (kept.Length != now.Length) kept = new T[now.Length];
            Array.Copy(now, kept, now.Length);
        }

        // A step that grew the arrays found them empty: they go back to all clear.
        static void Back<T>(T[] kept, T[] now, T[]? last)
        {
            if (kept.Length == now.Length) Array.Copy(kept, now, now.Length);
            else Array.Clear(now, 0, now.Length);
            if (last != null) Array.Clear(last, 0, last.Length);
        }

        /// <summary>Writes what the next step reads: which vertices an immovable shape held in the last substep, and the normals, which static friction held, which vertices' surface triangles a shape's feature met, and which vertices rest on a shape (with its normal and surface velocity there).</summary>
        internal void WriteState(StateWriter w)
        {
            w.WriteArray(_holdNow);
            w.WriteArray(_normal);
            w.WriteArray(_stuckNow);
            w.WriteArray(_featureMetNow);
            w.WriteArray(_restNow);
            w.WriteArray(_restNormalNow);
            w.WriteArray(_restVelocityNow);
        }

        /// <summary>Reads what <see cref="WriteState"/> wrote; the returned action applies it.</summary>
        internal Action PrepareRestore(StateReader r, int vertexCount)
        {
            bool[] held = r.ReadArray<bool>("soft contact holds");
            Vector3[] normal = r.ReadArrayExactly<Vector3>("soft contact normals", held.Length);
            bool[] stuck = r.ReadArrayExactly<bool>("soft contact static friction", held.Length);
            bool[] met = r.ReadArray<bool>("soft contact features met");
            if (met.Length != 0 && met.Length != vertexCount) throw r.Error($"soft contact features met for {met.Length} of {vertexCount} vertices.");
            if (held.Length != 0 && held.Length < vertexCount) throw r.Error($"soft contact holds for {held.Length} of {vertexCount} vertices.");
            bool[] rest = r.ReadArrayExactly<bool>("soft contact rests", held.Length);
            Vector3[] restNormal = r.ReadArrayExactly<Vector3>("soft contact rest normals", held.Length);
            Vector3[] restVelocity = r.ReadArrayExactly<Vector3>("soft contact rest surface velocities", held.Length);
            return () =>
            {
                _restNow = rest;
                _restLast = new bool[held.Length];
                _restNormalNow = restNormal;
                _restNormalLast = new Vector3[held.Length];
                _restVelocityNow = restVelocity;
                _restVelocityLast = new Vector3[held.Length];
                _holdNow = held;
                _holdLast = new bool[held.Length];
                _normal = normal;
                _stuckNow = stuck;
                _stuckLast = new bool[held.Length];
                _featureMetNow = met;
                _featureMetLast = new bool[met.Length];
                if (_pushed.Length != held.Length) AllocateSubstepScratch(held.Length);
            };
        }

        // The per-vertex arrays each substep starts from zero (BeginSubstep clears them).
        void AllocateSubstepScratch(int vertexCount)
        {
            _pushed = new float[vertexCount];
            _held = new float[vertexCount];
            _support = new float[vertexCount];
            _frictionMove = new Vector3[vertexCount];
            _patchVertex = new int[vertexCount];
            _patchTangent = new Vector3[vertexCount];
            _patchContact = new Vector3[vertexCount];
            _patchNormal = new Vector3[vertexCount];
            _patchSlip = new float[vertexCount];
            _newtonOwner = new int[vertexCount];
            _stick = new Vector3[vertexCount];
            _stickHeld = new float[vertexCount];
        }

        /// <summary>
        /// The vertices within reach of a dynamic body's shape now, for the Newton solver's
        /// coupled step (<see cref="ImplicitNewtonSolver"/>): per contact the vertex, the shape's
        /// outward normal, the contact point and the body's slot. Fills the arrays up to their
        /// length; returns how many.
        /// </summary>
        public int DynamicContacts(World world, SoftBody body, int[] vertex, Vector3[] normal, Vector3[] point, int[] owner, float[] friction)
        {
            ShapeStorage s = world.Shapes;
            BodyStorage b = world.Bodies;
            Vector3[] x = body.X;
            float[] free = body.FreeW;
            float radius = body.CollisionRadius;
            int count = 0;
            for (int k = 0; k < _count; k++)
            {
                int shape = _shapes[k];
                int slot = s.Body[shape];
                if (!RigidCoupling.Movable(b, slot)) continue;
                Pose pose = world.ShapeWorldPose(shape);
                ShapeGeometry geometry = s.Geometry[shape];
                float mu = Combine.Values(body.Friction, s.FrictionCombine[shape], s.Friction[shape], s.FrictionCombine[shape]);
                for (int i = 0; i < x.Length && count < vertex.Length; i++)
                {
                    if (free[i] == 0f) continue; // pinned or attached: see Solve
                    if (!ShapeDistance.Query(geometry, pose, x[i], radius, out float distance, out Vector3 n)) continue;
                    vertex[count] = i;
                    normal[count] = n;
                    point[count] = x[i] - n * distance;
                    owner[count] = slot;
                    friction[count] = mu;
                    count++;
                }
            }
            return count;
        }

        /// <summary>
        /// Records that the Newton solver's step met vertex <paramref name="i"/> against the
        /// dynamic body in <paramref name="slot"/> (normal and friction): the contact pass leaves
        /// that pair alone in this substep.
        /// </summary>
        public void MetByNewton(int i, int slot) => _newtonOwner[i] = slot + 1;


        /// <summary>
        /// Records the normal impulse (kg m) that a Newton step's spring against an immovable
        /// shape carried at vertex <paramref name="i"/> (the largest over the first iteration's
        /// steps; a later step's report replaces it, see <see cref="ReplaceSupport"/>):
        /// friction is bounded by mu times it as by the contact pass's own normal
        /// corrections. The springs hold a Newton body's vertices at the ground inside the step,
        /// so the pass after it had almost no normal correction left to bound friction by, and a
        /// Newton slab pushed at 1 m/s across the ground slid on at 0.99 m/s after 2 s.
        /// </summary>
        public void Support(int i, float impulse)
        {
            if (_supportReplaced)
            {
                Array.Clear(_support, 0, _support.Length);
                _supportReplaced = false;
            }
            if (impulse > _support[i]) _support[i] = impulse;
        }

        /// <summary>
        /// Starts a Newton step after the substep's first iteration: the supports it reports
        /// replace those recorded so far (a step that reports none, having converged or found no
        /// descent, leaves them). Each step measures the substep's whole normal impulse from its
        /// start, spread over the vertices by that step's springs; the largest per vertex over two
        /// steps whose springs held different vertices summed to up to twice the body's weight,
        /// and a Newton cube at two iterations held on every slope it should have slid down
        /// (friction 24 % above mu; keeping the largest over the steps within each iteration, it
        /// still slid up to 150 % slow). In the first iteration the largest of its steps stands
        /// (the step that follows a vertex entering a shape): replaced there too, at one iteration,
        /// soft fuzz seed 47 failed newly.
        /// </summary>
        public void ReplaceSupport() => _supportReplaced = true;

        /// <summary>
        /// True when vertex <paramref name="i"/> was within reach of an immovable shape in the last
        /// substep while its body was at rest (<see cref="HoldPatch"/>), with the shape's normal
        /// and the velocity of its surface there: the Newton step holds it across the normal
        /// (ImplicitNewtonSolver.Stick) and reports the friction that took (<see cref="Stuck"/>),
        /// which <see cref="CapSticks"/> holds to the patch's cone.
        /// </summary>
        public bool Sticks(int i, out Vector3 normal, out Vector3 surfaceVelocity)
        {
            bool sticks = i < _restLast.Length && _restLast[i];
            normal = sticks ? _restNormalLast[i] : Vector3.Zero;
            surfaceVelocity = sticks ? _restVelocityLast[i] : Vector3.Zero;
            return sticks;
        }

        /// <summary>The friction impulse (kg m, along the way the vertex was pulled) the Newton step's sticking spring carried at vertex <paramref name="i"/> in this substep.</summary>
        public void Stuck(int i, Vector3 impulse) => _stick[i] = impulse;

        /// <summary>True (with its normal) when an immovable shape pushed vertex <paramref name="i"/> in this substep or the last.</summary>
        public bool Touches(int i, out Vector3 normal)
        {
            normal = i < _normal.Length ? _normal[i] : default;
            return i < _holdNow.Length && (_holdNow[i] || _holdLast[i]);
        }

        /// <summary>Adds the friction's moves of the substep to the velocities (Newton bodies; see _frictionMove).</summary>
        public void ApplyFrictionVelocities(Vector3[] v, float[] w, float invH)
        {
            int n = Math.Min(v.Length, _frictionMove.Length);
            for (int i = 0; i < n; i++)
                if (w[i] != 0f) v[i] += _frictionMove[i] * invH;
        }

        /// <summary>Starts a substep: no vertex has been pushed or held yet.</summary>
        public void BeginSubstep(int vertexCount)
        {
            if (_pushed.Length < vertexCount)
            {
                AllocateSubstepScratch(vertexCount);
                _stuckNow = new bool[vertexCount];
                _stuckLast = new bool[vertexCount];
                _restNow = new bool[vertexCount];
                _restLast = new bool[vertexCount];
                _restVelocityNow = new Vector3[vertexCount];
                _restVelocityLast = new Vector3[vertexCount];
                _restNormalNow = new Vector3[vertexCount];
                _restNormalLast = new Vector3[vertexCount];
                _normal = new Vector3[vertexCount];
                _holdNow = new bool[vertexCount];
                _holdLast = new bool[vertexCount];
            }
            int triangles = _surface != null ? _surface.Length / 3 : 0;
            if (_trianglePushed.Length < triangles)
            {
                _trianglePushed = new float[triangles];
                _triangleHeld = new float[triangles];
            }
            if (_featureMetNow.Length < vertexCount)
            {
                Array.Resize(ref _featureMetNow, vertexCount);
                _featureMetLast = new bool[vertexCount];
            }
            Array.Clear(_trianglePushed, 0, _trianglePushed.Length);
            Array.Clear(_triangleHeld, 0, _triangleHeld.Length);
            bool[] met = _featureMetLast;
            _featureMetLast = _featureMetNow;
            _featureMetNow = met;
            Array.Clear(_featureMetNow, 0, _featureMetNow.Length);
            bool[] last = _holdLast;
            _holdLast = _holdNow;
            _holdNow = last;
            Array.Clear(_holdNow, 0, vertexCount);
            last = _stuckLast;
            _stuckLast = _stuckNow;
            _stuckNow = last;
            Array.Clear(_stuckNow, 0, vertexCount);
            last = _restLast;
            _restLast = _restNow;
            _restNow = last;
            Array.Clear(_restNow, 0, vertexCount);
            Vector3[] velocities = _restVelocityLast;
            _restVelocityLast = _restVelocityNow;
            _restVelocityNow = velocities;
            velocities = _restNormalLast;
            _restNormalLast = _restNormalNow;
            _restNormalNow = velocities;
            Array.Clear(_stick, 0, vertexCount);
            Array.Clear(_stickHeld, 0, vertexCount);
            Array.Clear(_pushed, 0, vertexCount);
            Array.Clear(_held, 0, vertexCount);
            Array.Clear(_support, 0, vertexCount);
            _supportReplaced = false;
            Array.Clear(_frictionMove, 0, vertexCount);
            Array.Clear(_newtonOwner, 0, vertexCount);
        }

        /// <summary>
        /// The deepest overlap of point <paramref name="x"/> (a vertex with the body's collision
        /// radius) with a static or kinematic candidate shape: the outward normal and the point
        /// on the surface offset by the radius. False when it overlaps none.
        /// </summary>
        public bool ImmovableOverlap(World world, SoftBody body, Vector3 x, out Vector3 normal, out Vector3 surface)
        {
            ShapeStorage s = world.Shapes;
            BodyStorage b = world.Bodies;
            float radius = body.CollisionRadius, deepest = 0f;
            normal = default;
            surface = default;
            for (int k = 0; k < _count; k++)
            {
                int shape = _shapes[k];
                if (RigidCoupling.Movable(b, s.Body[shape])) continue;
                if (!ShapeDistance.Query(s.Geometry[shape], world.ShapeWorldPose(shape), x, radius, out float distance, out Vector3 n)) continue;
                float depth = radius - distance;
                if (!(depth > deepest)) continue;
                deepest = depth;
                normal = n;
                surface = x + depth * n;
            }
            return deepest > 0f;
        }

        /// <summary>How closely a patch's slips must point one way for it to be held as one: 0.8 (see <see cref="HoldPatch"/>).</summary>
        const float Coherent = 0.8f;

        /// <summary>How many times its own cone a vertex of a resting patch may be held by: 2 (1.5 and 3 measured the same).</summary>
        const float Borrow = 2f;

        /// <summary>How far past the collision radius, as a fraction of it, a Newton body's friction reaches: 0.01 (see Solve).</summary>
        const float FrictionSkin = 0.01f;

        /// <summary>The speed (m/s) below which every vertex of a body must be for its patches to hold as one: 0.1.</summary>
        const float RestingSpeed = 0.1f;

        /// <summary>Whether every free vertex of the body started the substep slower than <see cref="RestingSpeed"/>.</summary>
        static bool Still(SoftBody body, Vector3 gravityStep)
        {
            Vector3[] v = body.V;
            float[] free = body.FreeW;
            for (int i = 0; i < v.Length; i++)
                if (free[i] != 0f && (v[i] - gravityStep).LengthSquared() >= RestingSpeed * RestingSpeed) return false;
            return true;
        }

        // A patch vertex that touched the shape in the last substep too, or was within its reach
        // while the body rested (not one arriving now).
        bool Settled(int p) => _holdLast[_patchVertex[p]] || _restLast[_patchVertex[p]];

        // A vertex of the patch taken with the others (HoldPatch): every vertex within reach of a
        // body at rest (the ground springs hold its vertices at the collision radius, and which
        // of them the contact pass pushed changes from substep to substep while the body's whole
        // weight is on them), else those that settled (not one arriving now).
        bool Member(int p, bool still) => still || Settled(p);

        /// <summary>
        /// Friction of a Newton body against one immovable shape, over the patch of its vertices
        /// touching it. The vertices that touched it in the last substep too are taken together
        /// when their slips point one way (the length of their sum at least
        /// <see cref="Coherent"/> times the sum of their lengths), like a rigid solver's manifold
        /// friction, within the cone of them all (mu times the sum of their normal impulses less
        /// the friction they spent):
        /// - resting (the slips need no more than that cone, every vertex of the body slower than
        ///   <see cref="RestingSpeed"/>, <see cref="Still"/>, and at least half of the patch stuck
        ///   in the last substep): every vertex is held, each by at most <see cref="Borrow"/> times
        ///   its own cone;
        /// - otherwise each vertex is held within its own cone, and the cone the vertices held
        ///   whole leave unused goes to those that slip, the same share of each one's excess (at
        ///   most <see cref="Borrow"/> times its own cone while the patch as a whole could hold),
        ///   so a sliding patch brakes with the cone of them all.
        /// The vertices arriving now, and patches whose slips spread apart (a slab crushed by a
        /// crate: the ground under its middle cannot hold its edges), take each vertex within its
        /// own cone. Of a body at rest every vertex within reach is taken with the patch, the
        /// friction its Newton step's sticking springs took is first held to the patch's cone
        /// (<see cref="CapSticks"/>), and the vertices stick in the next step (<see cref="Sticks"/>).
        /// Per vertex, the normal impulses a Newton step's springs measure (<see cref="Support"/>)
        /// spread over a face unlike the pull along it: resting, the vertices short of load
        /// slipped every substep, downhill only (a cube on a 30 degree slope at mu 0.8 crept
        /// 1.4 cm/s; now at most 0.3 mm/s); sliding, the few vertices carrying a stiff body's load
        /// were held whole by their own cones and the rest of those cones went unused (a cube of
        /// E 1e8 Pa slid on at 10 cm/s down a 20 degree slope at mu 0.5, braking at 74 % of the
        /// cone; now 5.1 cm/s). The resting hold is not for a body in motion (soft fuzz seed 93,
        /// a 4.8 t body crushing a 3.8 kg box, diverged), for vertices arriving (a nu 0.49 cube
        /// thrown at 10 m/s: the vertices beside its struck corner were held by its cone, min J
        /// 0.21-0.31 against 0.69), nor with no bound per vertex (a stiff slab holding a landed
        /// 1 t crate blew apart in one step, put back). Sharing out the spare cone only once the
        /// patch slid as a whole braked a struck corner harder (a nu 0.4999 cube thrown down and
        /// across at 10 m/s: min J 0.46; 0.62 now, 0.59 with each vertex in its own cone).
        /// </summary>
        void HoldPatch(SoftBody body, int count, float mu, int owner, RigidCoupling coupling, float h, Vector3 gravityStep, bool still)
        {
            CapSticks(body, count, mu, still);
            double cone = 0, need = 0;
            Vector3 net = Vector3.Zero;
            int members = 0, stuck = 0;
            for (int p = 0; p < count; p++)
            {
                if (!Member(p, still)) continue;
                int i = _patchVertex[p];
                members++;
                cone += mu * (_pushed[i] + _support[i]) - _held[i];
                need += _patchSlip[p];
                net += _patchSlip[p] * _patchTangent[p];
                if (_stuckLast[i]) stuck++;
            }
            bool coherent = members > 0 && net.Length() >= Coherent * need;
            bool holds = need <= cone;
            bool pooled = coherent && holds && still && 2 * stuck >= members;
            bool spill = coherent && !pooled;
            float share = 0f, limit = 1f;
            if (spill)
            {
                double spare = 0, deficit = 0;
                for (int p = 0; p < count; p++)
                {
                    if (!Member(p, still)) continue;
                    int i = _patchVertex[p];
                    float own = MathF.Max(0f, mu * (_pushed[i] + _support[i]) - _held[i]);
                    spare += Math.Max(0, own - _patchSlip[p]);
                    deficit += Math.Max(0, _patchSlip[p] - own);
                }
                share = deficit > 0 ? (float)Math.Min(1, spare / deficit) : 0f;
                // What the shares take, within what is left of the patch's cone: a vertex that lent
                // its cone in an earlier pass still has it by its own measure, and the end-of-substep
                // pass gave it out again (Newton cubes at two and three iterations slid up to 46 %
                // slow). Only for a free body, whose weight the patch alone carries: with the limit
                // for pinned and attached bodies too, three soft fuzz worlds of such bodies
                // (seeds 53, 77, 229) failed newly; that case is open (CHANGELOG, Known limits).
                if (Unpinned(body))
                {
                    double taken = 0;
                    for (int p = 0; p < count; p++) if (Member(p, still)) taken += SpillTake(p, mu, share, holds);
                    if (taken > Math.Max(0, cone)) limit = (float)(Math.Max(0, cone) / taken);
                }
            }
            for (int p = 0; p < count; p++)
            {
                int i = _patchVertex[p];
                float slip = _patchSlip[p], own = mu * (_pushed[i] + _support[i]) - _held[i], dlt;
                if (spill && Member(p, still))
                {
                    dlt = limit * SpillTake(p, mu, share, holds);
                    if (slip <= MathF.Max(0f, own) && slip > 0f && limit == 1f) _stuckNow[i] = true;
                }
                else if (pooled && Member(p, still))
                {
                    float most = Borrow * MathF.Max(0f, own);
                    dlt = MathF.Min(slip, most);
                    if (slip <= most) _stuckNow[i] = true;
                }
                else
                {
                    if (slip == 0f) continue;
                    dlt = slip;
                    if (dlt > own) dlt = MathF.Max(0f, own);
                    else _stuckNow[i] = true;
                }
                Slide(body, i, owner, _patchContact[p], _patchTangent[p], dlt, coupling, h, gravityStep);
            }
            // A body at rest on the shape sticks to it in the next substep's Newton step (Sticks).
            if (!still || !Unpinned(body)) return;
            for (int p = 0; p < count; p++)
            {
                int i = _patchVertex[p];
                _restNow[i] = true;
                _restVelocityNow[i] = coupling.PointVelocity(owner, _patchContact[p]);
                _restNormalNow[i] = _patchNormal[p];
            }
        }

        // The correction a member of a spilling patch takes (HoldPatch): its own slip within its own
        // cone, and the given share of the excess beyond it (at most Borrow times the cone while the
        // patch as a whole could hold).
        float SpillTake(int p, float mu, float share, bool holds)
        {
            int i = _patchVertex[p];
            float slip = _patchSlip[p], cap = MathF.Max(0f, mu * (_pushed[i] + _support[i]) - _held[i]);
            float dlt = slip <= cap ? slip : cap + share * (slip - cap);
            return holds ? MathF.Min(dlt, Borrow * cap) : dlt;
        }

        /// <summary>
        /// The friction the Newton step's sticking springs took at this patch (<see cref="Sticks"/>,
        /// reported by <see cref="Stuck"/>), as one force like a rigid solver's manifold friction,
        /// within the patch's cone: beyond it the whole body slides on by the excess, spread over
        /// its mass (Coulomb's kinetic friction), and the cone it used is spent.
        /// </summary>
        void CapSticks(SoftBody body, int count, float mu, bool still)
        {
            Vector3 sticks = Vector3.Zero;
            for (int p = 0; p < count; p++) if (Member(p, still)) sticks += _stick[_patchVertex[p]];
            if (sticks == Vector3.Zero) return;
            // A later iteration's step holds the body from the substep's start again, and its
            // report replaces the last: the cone an earlier one spent is given back first.
            double cone = 0;
            for (int p = 0; p < count; p++)
            {
                if (!Member(p, still)) continue;
                int i = _patchVertex[p];
                _held[i] -= _stickHeld[i];
                _stickHeld[i] = 0f;
                cone += MathF.Max(0f, mu * (_pushed[i] + _support[i]) - _held[i]);
            }
            float taken = sticks.Length();
            if (taken > cone)
            {
                Vector3 excess = (float)((taken - cone) / taken) * sticks;
                Vector3[] x = body.X;
                float[] m = body.M, free = body.FreeW;
                double mass = 0;
                for (int i = 0; i < x.Length; i++) if (free[i] != 0f) mass += m[i];
                if (mass > 0)
                {
                    Vector3 d = excess / (float)mass;
                    for (int i = 0; i < x.Length; i++) if (free[i] != 0f) x[i] += d;
                }
            }
            float used = cone > 0 ? (float)Math.Min(1.0, taken / cone) : 0f;
            for (int p = 0; p < count; p++)
            {
                if (!Member(p, still)) continue;
                int i = _patchVertex[p];
                _stickHeld[i] = used * MathF.Max(0f, mu * (_pushed[i] + _support[i]) - _held[i]);
                _held[i] += _stickHeld[i];
                _stick[i] = Vector3.Zero;
            }
        }

        // Whether every vertex of the body is free (nothing pinned or attached): only such a body
        // sticks as a whole and slides on by a uniform move (CapSticks).
        static bool Unpinned(SoftBody body)
        {
            float[] free = body.FreeW;
            for (int i = 0; i < free.Length; i++) if (free[i] == 0f) return false;
            return true;
        }

        // Friction's correction dlt (kg m) at vertex i along -t, counted against the cone. For a
        // Newton body, the slip the vertex brought in with its velocity (all of it unless static
        // friction held the vertex in the last substep too) is taken out of the velocity and
        // left to the next implicit step; only what the substep's own forces added to a resting
        // contact (gravity along a slope, the elastic pull) comes out of the position. Taken out
        // of the position alone, friction braking a struck corner sheared it (a cube at nu 0.4999
        // thrown down and across at 10 m/s: min J 0.15) and stored strain the motion did not hold
        // (a Newton beam landing gained energy, soft fuzz seed 12); out of the velocity alone, a
        // body resting on a slope crept 7 cm/s.
        void Slide(SoftBody body, int i, int owner, Vector3 contact, Vector3 t, float dlt, RigidCoupling coupling, float h, Vector3 gravityStep)
        {
            float wi = body.W[i];
            _held[i] += dlt;
            if (body.Solver == SoftSolver.Newton)
            {
                Vector3 incoming = (body.V[i] - gravityStep - coupling.PointVelocity(owner, contact)) * h;
                float carried = _stuckLast[i] ? MathF.Min(wi * dlt, MathF.Max(0f, Vector3.Dot(incoming, t))) : wi * dlt;
                _frictionMove[i] -= carried * t;
                body.X[i] -= (wi * dlt - carried) * t;
            }
            else body.X[i] -= wi * dlt * t;
            coupling.Push(owner, contact, dlt * t, h);
        }

        /// <summary>
        /// One pass over the gathered shapes for every free vertex, in a fixed order: the normal
        /// constraint when <paramref name="normal"/> (before the elastic pass), then friction on
        /// the whole tangential displacement of the substep so far, bounded by mu times the
        /// normal corrections the vertex had in the substep less the friction already spent (a
        /// Newton body against an immovable shape: patch by patch, <see cref="HoldPatch"/>).
        /// Without <paramref name="friction"/>, the normal constraint alone: a Newton body's
        /// passes between its iterations, where the next step would undo friction's moves while
        /// the cone they spent stayed spent.
        /// </summary>
        public void Solve(World world, SoftBody body, float h, RigidCoupling coupling, bool normal, bool friction = true)
        {
            ShapeStorage s = world.Shapes;
            Vector3[] x = body.X, xPrev = body.XPrev;
            float[] w = body.W, free = body.FreeW;
            float radius = body.CollisionRadius;
            bool byVelocity = body.Solver == SoftSolver.Newton;
            Vector3 gravityStep = body.GravityStep(h);
            bool still = byVelocity && Still(body, gravityStep);
            // A Newton body's vertices rest where the contact pass put them, at the collision
            // radius, held there by the step's springs (whose normal impulses bound friction):
            // friction reaches them a little past it.
            float reach = byVelocity ? radius * (1f + FrictionSkin) : radius;
            for (int k = 0; k < _count; k++)
            {
                int shape = _shapes[k];
                int owner = s.Body[shape];
                Pose pose = world.ShapeWorldPose(shape);
                ShapeGeometry geometry = s.Geometry[shape];
                float mu = Combine.Values(body.Friction, s.FrictionCombine[shape], s.Friction[shape], s.FrictionCombine[shape]);
                // A Newton body's friction against an immovable shape goes patch by patch.
                bool patchFriction = byVelocity && !RigidCoupling.Movable(world.Bodies, owner);
                int patch = 0;
                for (int i = 0; i < x.Length; i++)
                {
                    // Pinned and attached vertices (no free inverse mass) take no contacts: an
                    // attached vertex moves with its body, whose own shapes meet the world.
                    // Pushed out of the ground while its body held it there (a cloth pinned to a
                    // 9 t body that came to rest over it), the contact and the attachment fought
                    // every iteration, and the velocities of that fight, handed to the body,
                    // spun it up to 400 rad/s.
                    if (free[i] == 0f) continue;
                    float wi = w[i];
                    // A contact the Newton solver's step has met (added mass, with friction; see
                    // ImplicitNewtonSolver) is not projected again: pushing the vertex alone
                    // crushed a stiff slab under a dropped crate, pushing the body alone lifted a
                    // resting plate onto its highest vertex. What overlap is left the next step meets.
                    if (_newtonOwner[i] == owner + 1) continue;
                    if (!ShapeDistance.Query(geometry, pose, x[i], reach, out float distance, out Vector3 n)) continue;
                    Vector3 contact = x[i] - n * distance;
                    float wb = coupling.InverseMassAt(owner, contact, n);
                    if (normal && distance < radius)
                    {
                        float dl = (radius - distance) / (wi + wb);
                        x[i] += wi * dl * n;
                        coupling.Push(owner, contact, -dl * n, h);
                        _pushed[i] += dl;
                        if (wb == 0f)
                        {
                            _normal[i] = n;
                            _holdNow[i] = true;
                        }
                    }

                    if (!friction) continue;
                    Vector3 relative = (x[i] + _frictionMove[i] - xPrev[i]) - coupling.PointVelocity(owner, contact) * h;
                    Vector3 tangent = relative - Vector3.Dot(relative, n) * n;
                    float slip = tangent.Length();
                    if (patchFriction)
                    {
                        // Gathered, then held together within the patch's cone (HoldPatch); a
                        // vertex that did not slip still adds its normal impulse to the cone.
                        Vector3 along = slip < 1e-9f ? Vector3.Zero : tangent / slip;
                        _patchVertex[patch] = i;
                        _patchTangent[patch] = along;
                        _patchContact[patch] = contact;
                        _patchNormal[patch] = n;
                        _patchSlip[patch++] = slip < 1e-9f ? 0f : slip / wi;
                        continue;
                    }
                    if (slip < 1e-9f) continue;
                    Vector3 t = tangent / slip;
                    float dlt = slip / (wi + coupling.InverseMassAt(owner, contact, t));
                    // Static friction holds the whole slip; beyond the cone the correction is capped.
                    float cone = mu * (_pushed[i] + _support[i]) - _held[i];
                    if (dlt > cone) dlt = MathF.Max(0f, cone);
                    else if (wb == 0f) _stuckNow[i] = true;
                    Slide(body, i, owner, contact, t, dlt, coupling, h, gravityStep);
                }
                if (patch > 0) HoldPatch(body, patch, mu, owner, coupling, h, gravityStep, still);
                // The shape's corners and edges against the surface triangles (a tet body's).
                if (normal && body.Tets.Length > 0 && geometry.Type != ShapeType.Plane
                    && !(RigidCoupling.Movable(world.Bodies, owner) && world.Bodies.Mass[owner] > ShapeFeatureContacts.MaxLoadRatio * body.TotalMass))
                    ShapeFeatureContacts.Solve(body, _surface!, _apex, _restVolume6, geometry, pose, owner, coupling, h, friction ? mu : 0f, _trianglePushed, _triangleHeld, _featureMetLast, _featureMetNow);
            }
            // Meshes only before the elastic pass: a second friction pass there let a jelly falling
            // at 4 m/s onto a mesh floor end 2.5 mm deep (the bound is 2 mm).
            if (normal && _meshes.Count > 0) _meshes.Solve(body, _pushed, _held);
        }
    }
}
