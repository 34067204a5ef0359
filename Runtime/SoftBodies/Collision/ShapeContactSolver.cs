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
    internal sealed partial class ShapeContactSolver
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
                if (normal && body.Attachments.Length > 0 && !byVelocity && !RigidCoupling.Movable(world.Bodies, owner)) AnchorsOut(world, body, geometry, pose, owner, coupling, h);
                // The shape's corners and edges against the surface triangles (a tet body's).
                if (normal && body.Tets.Length > 0 && geometry.Type != ShapeType.Plane
                    && !(RigidCoupling.Movable(world.Bodies, owner) && world.Bodies.Mass[owner] > ShapeFeatureContacts.MaxLoadRatio * body.TotalMass))
                    ShapeFeatureContacts.Solve(body, _surface!, _apex, _restVolume6, geometry, pose, owner, coupling, h, friction ? mu : 0f, _trianglePushed, _triangleHeld, _featureMetLast, _featureMetNow);
            }
            // Meshes only before the elastic pass: a second friction pass there let a jelly falling
            // at 4 m/s onto a mesh floor end 2.5 mm deep (the bound is 2 mm).
            if (normal && _meshes.Count > 0) _meshes.Solve(body, _pushed, _held);
        }

        /// <summary>
        /// The anchors of the body's attachments to dynamic bodies that lie inside the immovable
        /// shape of <paramref name="owner"/> push their body out to its surface, with the vertices
        /// attached to it (<see cref="AttachmentSolver.MoveWhole"/>), as a rigid contact at the
        /// anchor would. An attached vertex takes no contact of its own (it moves with its
        /// body: see Solve), and an anchor off the body's shapes meets nothing else: a 124 kg body
        /// swinging a 0.16 kg box on a 3.5 m lever drove the box's attached end 0.33 m into the
        /// ground, and the contacts pushing its free vertices out crushed the tets between
        /// through J = 0 (soft fuzz seed 73). Only anchors deeper inside the shape than twice the
        /// rigid contacts' <see cref="WorldSettings.LinearSlop"/>, and out to that depth: a body
        /// resting on the ground with a cloth attached under it has its anchors on the ground, as
        /// deep as the body's own contacts leave it, and pushing those out fights them (at the
        /// slop itself, a 10 g body resting on a slope with a 6 kg sphere hanging from it was
        /// nudged every substep, and the run took another course: soft fuzz seed 21).
        /// The push is bounded like a rigid contact's (the anchor's speed into the shape plus
        /// <see cref="WorldSettings.MaxContactPushSpeed"/>, over the substep). XPBD bodies only:
        /// a Newton body's step moves the bodies it is attached to as part of its own solve, and
        /// pushed here as well, a 20 g body holding two Newton bodies by pins gained 31 J on
        /// landing (492 J for a 2 kg one with the push bounded by the inward motion alone;
        /// CouplingTests). A Newton body's anchors still meet nothing.
        /// </summary>
        void AnchorsOut(World world, SoftBody body, in ShapeGeometry geometry, in Pose pose, int owner, RigidCoupling coupling, float h)
        {
            BodyStorage b = world.Bodies;
            Attachment[] attachments = body.Attachments;
            float[] w = body.W;
            for (int k = 0; k < attachments.Length; k++)
            {
                ref Attachment a = ref attachments[k];
                int slot = a.BodySlot;
                if (slot == owner || w[a.Vertex] == 0f || !AttachmentSolver.Anchor(b, a, out Vector3 anchor) || !RigidCoupling.Movable(b, slot)) continue;
                float slop = 2f * world.Settings.LinearSlop; // see above
                if (!ShapeDistance.Query(geometry, pose, anchor, 0f, out float distance, out Vector3 n) || !(distance < -slop)) continue;
                // Out by what the anchor moved in within this substep, and by the world's
                // contact push speed beyond that: a push changes the body's velocity by the move
                // over h, so one deep anchor pushed out at once would throw its body off.
                float inward = MathF.Max(0f, -Vector3.Dot(coupling.PointVelocity(slot, anchor), n));
                float move = MathF.Min(-distance - slop, (inward + world.Settings.MaxContactPushSpeed) * h);
                if (move > 0f) AttachmentSolver.MoveWhole(world, body, slot, anchor, n, move, h, coupling);
            }
        }
    }
}
