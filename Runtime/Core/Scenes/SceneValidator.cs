using System;
using System.Collections.Generic;
using System.Globalization;
using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// Checks a <see cref="SceneDocument"/> against the rules of the scene format: value ranges,
    /// the format tag, which shapes a body type may carry, mass versus density, and that every
    /// material, body and joint name referred to exists and every name is unique (generated
    /// names included). Each error names the JSON path of the offending value, computed from
    /// the document's structure, so documents built in code are checked the same way.
    /// </summary>
    public static class SceneValidator
    {
        /// <summary>The most bodies a scene may expand to (a typo in a count should not exhaust memory).</summary>
        public const long MaxBodies = 1_000_000;

        /// <summary>The most cells a soft mesh grid may have along one axis (the soft-body meshers' limit).</summary>
        public const int MaxGridCells = 1024;

        /// <summary>Every problem found, in document order; empty when the document is valid.</summary>
        public static IReadOnlyList<SceneError> Validate(SceneDocument doc)
        {
            var v = new Checker();
            v.Document(doc);
            return v.Errors;
        }

        /// <summary>Throws a <see cref="SceneException"/> listing every problem, if there is any.</summary>
        public static void ThrowIfInvalid(SceneDocument doc)
        {
            IReadOnlyList<SceneError> errors = Validate(doc);
            if (errors.Count > 0) throw new SceneException(errors);
        }

        sealed class Checker
        {
            public readonly List<SceneError> Errors = new List<SceneError>();
            SceneDocument _doc = null!;
            bool _generatorsExpanded;

            void Error(string path, string message) => Errors.Add(new SceneError(path, message));

            static string F(float f) => f.ToString("R", CultureInfo.InvariantCulture);

            static string V(Vector3 v) => $"[{F(v.X)}, {F(v.Y)}, {F(v.Z)}]";

            static string P(string parent, string key) => JsonPath.Member(parent, key);

            public void Document(SceneDocument doc)
            {
                _doc = doc;
                const string root = JsonPath.Root;
                if (doc.Format != SceneDocument.CurrentFormat)
                    Error(P(root, "format"), $"must be \"{SceneDocument.CurrentFormat}\", got {JsonPath.Quote(doc.Format ?? "")}");
                if (Finite(doc.Gravity, P(root, "gravity")) && Limits.Length(doc.Gravity) > Limits.MaxGravity)
                    Error(P(root, "gravity"), $"must have magnitude at most {F(Limits.MaxGravity)} m/s^2 (Limits.MaxGravity), got {V(doc.Gravity)}");
                if (Positive(doc.Timestep, P(root, "timestep"))) Upto(doc.Timestep, Limits.MinTimeStep, Limits.MaxTimeStep, P(root, "timestep"), "Limits.MinTimeStep/MaxTimeStep");
                string solver = P(root, "solver");
                if (doc.Solver == null) Error(solver, "must not be null");
                else
                {
                    if (doc.Solver.Type != SolverType.Pgs && doc.Solver.Type != SolverType.Tgs) Error(P(solver, "type"), "must be pgs or tgs");
                    if (AtLeast(doc.Solver.Iterations, 1, P(solver, "iterations"))) IntInRange(doc.Solver.Iterations, 1, Limits.MaxIterations, P(solver, "iterations"));
                    if (AtLeast(doc.Solver.Substeps, 1, P(solver, "substeps"))) IntInRange(doc.Solver.Substeps, 1, Limits.MaxSubsteps, P(solver, "substeps"));
                    if (doc.Solver.ContactHertz is float contactHertz) Positive(contactHertz, P(solver, "contactHertz"));
                    if (doc.Solver.JointHertz is float jointHertz) Positive(jointHertz, P(solver, "jointHertz"));
                    if (doc.Solver.ManifoldReuse is float reuse) NonNegative(reuse, P(solver, "manifoldReuse"));
                    if (doc.Solver.ShockDepth is float shockDepth) NonNegative(shockDepth, P(solver, "shockDepth"));
                    if (doc.Solver.MaxJointCorrectionSpeed is float jointSpeed) Positive(jointSpeed, P(solver, "maxJointCorrectionSpeed"));
                }
                Materials();
                for (int i = 0; i < doc.Bodies.Count; i++) Body(doc.Bodies[i], JsonPath.Index("$.bodies", i));
                bool generatorsOk = Generators();
                HashSet<string> bodies = BodyNames(generatorsOk);
                _generatorsExpanded = generatorsOk;
                for (int i = 0; i < doc.Joints.Count; i++) Joint(doc.Joints[i], JsonPath.Index("$.joints", i), bodies);
                if (generatorsOk) JointNames();
                var softNames = new Dictionary<string, string>();
                for (int i = 0; i < doc.SoftBodies.Count; i++) SoftBody(doc.SoftBodies[i], JsonPath.Index("$.softBodies", i), bodies, softNames);
            }

            void Materials()
            {
                var seen = new HashSet<string>();
                foreach (SceneMaterial m in _doc.Materials)
                {
                    string path = JsonPath.Member("$.materials", m.Name ?? "");
                    if (string.IsNullOrEmpty(m.Name)) Error(path, "a material needs a non-empty name");
                    else if (!seen.Add(m.Name)) Error(path, $"duplicate material name '{m.Name}'");
                    NonNegative(m.Friction, P(path, "friction"));
                    InRange(m.Restitution, 0, 1, P(path, "restitution"));
                    if (m.Density is float density) Positive(density, P(path, "density"));
                }
            }

            void Body(SceneBody b, string path)
            {
                if (b == null) { Error(path, "must not be null"); return; }
                if (string.IsNullOrEmpty(b.Name)) Error(P(path, "name"), "must be a non-empty name");
                if (b.Type != BodyType.Static && b.Type != BodyType.Kinematic && b.Type != BodyType.Dynamic)
                    Error(P(path, "type"), "must be static, kinematic or dynamic");
                if (b.Shape == null) Error(P(path, "shape"), "missing required field");
                else Shape(b.Shape, P(path, "shape"), b.Type == BodyType.Static, child: false);
                MassAndMaterial(b.Mass, b.Material, b.Type, path);
                if (b.Density is float density && Positive(density, P(path, "density")) && b.Mass != null)
                    Error(P(path, "density"), "mass and density are both given: give one");
                Coordinate(b.Position, P(path, "position"));
                Rotation(b.Rotation, P(path, "rotation"));
                Speed(b.Velocity, P(path, "velocity"));
                Speed(b.AngularVelocity, P(path, "angularVelocity"));
                if (b.Type == BodyType.Static)
                {
                    if (b.Velocity != Vector3.Zero) Error(P(path, "velocity"), "a static body cannot move: must be [0, 0, 0]");
                    if (b.AngularVelocity != Vector3.Zero) Error(P(path, "angularVelocity"), "a static body cannot move: must be [0, 0, 0]");
                    if (b.Ccd) Error(P(path, "ccd"), "a static body cannot use continuous collision");
                }
                if ((b.LockAxes & ~AxisLocks.All) != 0)
                    Error(P(path, "lockAxes"), $"unknown axis bits 0x{(int)b.LockAxes:X} (AxisLocks has linearX/Y/Z and angularX/Y/Z)");
                else if (b.LockAxes != AxisLocks.None && b.Type != BodyType.Dynamic)
                    Error(P(path, "lockAxes"), $"a {SceneNames.Of(b.Type)} body is not moved by the solver: axis locks are for dynamic bodies");
            }

            void MassAndMaterial(float? mass, string? material, BodyType type, string path)
            {
                if (material != null)
                {
                    if (_doc.FindMaterial(material) == null) Error(P(path, "material"), $"no material named '{material}' in $.materials");
                }
                if (mass is float kg)
                {
                    if (type != BodyType.Dynamic) Error(P(path, "mass"), $"a {SceneNames.Of(type)} body has no mass: remove it or make the body dynamic");
                    else if (Positive(kg, P(path, "mass"))) Upto(kg, Limits.MinMass, Limits.MaxMass, P(path, "mass"), "Limits.MinMass/MaxMass");
                }
            }

            void Shape(SceneShape s, string path, bool isStatic, bool child)
            {
                switch (s)
                {
                    case SceneSphere sphere:
                        Size(sphere.Radius, P(path, "radius"));
                        break;
                    case SceneBox box:
                        Size(box.HalfExtents, P(path, "halfExtents"));
                        break;
                    case SceneCapsule capsule:
                        Size(capsule.Radius, P(path, "radius"));
                        if (NonNegative(capsule.HalfHeight, P(path, "halfHeight"))) Upto(capsule.HalfHeight, 0, Limits.MaxShapeSize, P(path, "halfHeight"), "Limits.MaxShapeSize");
                        break;
                    case SceneConvex convex:
                        if (convex.Points.Count < 4) Error(P(path, "points"), $"a convex hull needs at least 4 points, got {convex.Points.Count}");
                        if (convex.Points.Count > Limits.MaxHullPoints)
                            Error(P(path, "points"), $"at most {Limits.MaxHullPoints} points (Limits.MaxHullPoints), got {convex.Points.Count}");
                        else
                            for (int i = 0; i < convex.Points.Count; i++) Extent(convex.Points[i], JsonPath.Index(P(path, "points"), i));
                        break;
                    case ScenePlane plane:
                        if (child) Error(P(path, "type"), "a plane cannot be a compound child");
                        else if (!isStatic) Error(P(path, "type"), "a plane can only be the shape of a static body");
                        if (Finite(plane.Normal, P(path, "normal")) && !(plane.Normal.Length() > 1e-6f)) Error(P(path, "normal"), "must be non-zero");
                        if (Finite(plane.Offset, P(path, "offset"))) Upto(plane.Offset, -Limits.MaxPosition, Limits.MaxPosition, P(path, "offset"), "Limits.MaxPosition");
                        break;
                    case SceneMesh mesh:
                        if (child) Error(P(path, "type"), "a mesh cannot be a compound child");
                        else if (!isStatic) Error(P(path, "type"), "a mesh can only be the shape of a static body");
                        Mesh(mesh, path);
                        break;
                    case SceneCompound compound:
                        if (child) { Error(P(path, "type"), "compounds cannot be nested"); break; }
                        string children = P(path, "children");
                        if (compound.Children.Count == 0) Error(children, "a compound needs at least one child");
                        for (int i = 0; i < compound.Children.Count; i++)
                        {
                            SceneCompoundChild c = compound.Children[i];
                            string cp = JsonPath.Index(children, i);
                            if (c.Shape == null) Error(P(cp, "shape"), "missing required field");
                            else Shape(c.Shape, P(cp, "shape"), isStatic, child: true);
                            Extent(c.Position, P(cp, "position"));
                            Rotation(c.Rotation, P(cp, "rotation"));
                        }
                        break;
                }
            }

            void Mesh(SceneMesh mesh, string path)
            {
                string vertices = P(path, "vertices"), triangles = P(path, "triangles");
                if (mesh.Vertices.Count < 3) Error(vertices, $"a mesh needs at least 3 vertices, got {mesh.Vertices.Count}");
                for (int i = 0; i < mesh.Vertices.Count; i++) Coordinate(mesh.Vertices[i], JsonPath.Index(vertices, i));
                if (mesh.Triangles.Count == 0 || mesh.Triangles.Count % 3 != 0)
                    Error(triangles, $"needs at least one triangle of 3 indices, got {mesh.Triangles.Count} indices");
                for (int i = 0; i < mesh.Triangles.Count; i++)
                {
                    int index = mesh.Triangles[i];
                    if (index < 0 || index >= mesh.Vertices.Count)
                        Error(JsonPath.Index(JsonPath.Index(triangles, i / 3), i % 3), $"vertex index {index} is out of range 0..{mesh.Vertices.Count - 1}");
                }
            }

            // Checks each generator alone; true when all are fine to expand.
            bool Generators()
            {
                bool ok = true;
                long total = _doc.Bodies.Count;
                for (int k = 0; k < _doc.Generators.Count; k++)
                {
                    SceneGenerator g = _doc.Generators[k];
                    string path = JsonPath.Index("$.generators", k);
                    int before = Errors.Count;
                    if (g.Name != null && g.Name.Length == 0) Error(P(path, "name"), "must be a non-empty name (or left out)");
                    Coordinate(g.At, P(path, "at"));
                    Size(g.Size, P(path, "size"));
                    if (NonNegative(g.Spacing, P(path, "spacing"))) Upto(g.Spacing, 0, Limits.MaxShapeSize, P(path, "spacing"), "Limits.MaxShapeSize");
                    MassAndMaterial(g.Mass, g.Material, BodyType.Dynamic, path);
                    switch (g)
                    {
                        case SceneTower t: AtLeast(t.Count, 1, P(path, "count")); break;
                        case ScenePyramid p: AtLeast(p.Count, 1, P(path, "count")); break;
                        case SceneChain c: AtLeast(c.Count, 1, P(path, "count")); break;
                        case SceneDominoes d:
                            AtLeast(d.Count, 1, P(path, "count"));
                            if (Finite(d.TipSpeed, P(path, "tipSpeed"))) Upto(d.TipSpeed, -Limits.MaxInputSpeed, Limits.MaxInputSpeed, P(path, "tipSpeed"), "Limits.MaxInputSpeed");
                            break;
                        case SceneWall w:
                            if (AtLeast(w.Count, 1, P(path, "count")) && w.Staggered && w.Count < 2)
                                Error(P(path, "count"), "a staggered wall needs at least 2 bricks per row (or \"staggered\": false)");
                            AtLeast(w.Rows, 1, P(path, "rows"));
                            break;
                        case ScenePile pile:
                            if (pile.Grid == null || pile.Grid.Length != 3) Error(P(path, "grid"), "must be [nx, ny, nz]");
                            else
                                for (int a = 0; a < 3; a++) AtLeast(pile.Grid[a], 1, JsonPath.Index(P(path, "grid"), a));
                            if (pile.Shape != SceneShapeType.Box && pile.Shape != SceneShapeType.Sphere && pile.Shape != SceneShapeType.Capsule)
                                Error(P(path, "shape"), "must be box, sphere or capsule");
                            break;
                    }
                    if (Errors.Count != before) { ok = false; continue; }
                    long count = g.BodyCount;
                    if (count < 0 || count > MaxBodies - total) { Error(path, $"the scene would have more than {MaxBodies} bodies"); ok = false; }
                    else total += count;
                }
                return ok;
            }

            // The set of all body names, reporting duplicates (generated names included when the generators are fine).
            HashSet<string> BodyNames(bool withGenerated)
            {
                var first = new Dictionary<string, string>();
                for (int i = 0; i < _doc.Bodies.Count; i++)
                {
                    string? name = _doc.Bodies[i]?.Name;
                    if (string.IsNullOrEmpty(name)) continue;
                    string path = JsonPath.Index("$.bodies", i);
                    if (first.TryGetValue(name!, out string? at)) Error(P(path, "name"), $"duplicate body name '{name}' (first used at {at})");
                    else first.Add(name!, path);
                }
                if (withGenerated)
                {
                    var bodies = new List<SceneBody>();
                    var joints = new List<SceneJoint>();
                    for (int k = 0; k < _doc.Generators.Count; k++)
                    {
                        string path = JsonPath.Index("$.generators", k);
                        bodies.Clear();
                        _doc.Generators[k].Expand(bodies, joints);
                        foreach (SceneBody b in bodies)
                        {
                            if (first.TryGetValue(b.Name, out string? at))
                            {
                                Error(path, $"generated body name '{b.Name}' is already used at {at}: give the generator a \"name\"");
                                break;
                            }
                            first.Add(b.Name, path);
                        }
                    }
                }
                return new HashSet<string>(first.Keys);
            }

            void JointNames()
            {
                SceneExpansion e = _doc.Expand();
                var first = new Dictionary<string, string>();
                for (int i = 0; i < e.Joints.Count; i++)
                {
                    string? name = e.Joints[i]?.Name;
                    if (name == null) continue;
                    string source = e.JointSources[i];
                    bool generated = i >= _doc.Joints.Count;
                    if (first.TryGetValue(name, out string? at))
                        Error(generated ? source : P(source, "name"), $"duplicate joint name '{name}' (first used at {at})");
                    else first.Add(name, source);
                }
            }

            // When a generator was rejected its bodies were never made: a name that would be one
            // of them gets the benefit of the doubt rather than a second, misleading error.
            bool Exists(string name, HashSet<string> bodies)
            {
                if (bodies.Contains(name)) return true;
                if (_generatorsExpanded) return false;
                foreach (SceneGenerator g in _doc.Generators)
                    if (name.StartsWith(g.Prefix + "/", StringComparison.Ordinal)) return true;
                return false;
            }

            void Joint(SceneJoint j, string path, HashSet<string> bodies)
            {
                if (j == null) { Error(path, "must not be null"); return; }
                if (j.Name != null && j.Name.Length == 0) Error(P(path, "name"), "must be a non-empty name (or left out)");
                if (j.BodyA == null && j.BodyB == null) Error(path, "bodyA and bodyB cannot both be the world (null)");
                if (j.BodyA != null && !Exists(j.BodyA, bodies)) Error(P(path, "bodyA"), $"no body named '{j.BodyA}'");
                if (j.BodyB != null && !Exists(j.BodyB, bodies)) Error(P(path, "bodyB"), $"no body named '{j.BodyB}'");
                if (j.BodyA != null && j.BodyA == j.BodyB) Error(P(path, "bodyB"), "a joint needs two different bodies");
                Coordinate(j.AnchorA, P(path, "anchorA"));
                Coordinate(j.AnchorB, P(path, "anchorB"));
                if (j.BreakForce is float force) Positive(force, P(path, "breakForce"));
                if (j.BreakTorque is float torque) Positive(torque, P(path, "breakTorque"));
                if (j.FrictionTorque is float friction) NonNegative(friction, P(path, "frictionTorque"));
                if (j is SceneAxisPairJoint axes)
                {
                    Axis(axes.AxisA, P(path, "axisA"));
                    Axis(axes.AxisB, P(path, "axisB"));
                }
                switch (j)
                {
                    case SceneHingeJoint h:
                        if (h.LowerDeg is float lo) InRange(lo, -180, 180, P(path, "lowerDeg"));
                        if (h.UpperDeg is float hi) InRange(hi, -180, 180, P(path, "upperDeg"));
                        if (h.LowerDeg > h.UpperDeg) Error(P(path, "upperDeg"), $"must be >= lowerDeg ({F(h.LowerDeg!.Value)}), got {F(h.UpperDeg!.Value)}");
                        Finite(h.MotorSpeed, P(path, "motorSpeed"));
                        NonNegative(h.MaxMotorTorque, P(path, "maxMotorTorque"));
                        break;
                    case SceneDistanceJoint d:
                        if (d.MinLength is float min) NonNegative(min, P(path, "minLength"));
                        if (d.MaxLength is float max) NonNegative(max, P(path, "maxLength"));
                        if (d.MinLength > d.MaxLength) Error(P(path, "maxLength"), $"must be >= minLength ({F(d.MinLength!.Value)}), got {F(d.MaxLength!.Value)}");
                        NonNegative(d.StiffnessHz, P(path, "stiffnessHz"));
                        NonNegative(d.Damping, P(path, "damping"));
                        break;
                    case ScenePrismaticJoint p:
                        Axis(p.AxisA, P(path, "axisA"));
                        if (p.Lower is float l) Finite(l, P(path, "lower"));
                        if (p.Upper is float u) Finite(u, P(path, "upper"));
                        if (p.Lower > p.Upper) Error(P(path, "upper"), $"must be >= lower ({F(p.Lower!.Value)}), got {F(p.Upper!.Value)}");
                        break;
                    case SceneConeTwistJoint c:
                        InRange(c.ConeDeg, 0, 180, P(path, "coneDeg"));
                        InRange(c.TwistDeg, 0, 180, P(path, "twistDeg"));
                        break;
                }
            }

            void SoftBody(SceneSoftBody s, string path, HashSet<string> bodies, Dictionary<string, string> names)
            {
                if (s == null) { Error(path, "must not be null"); return; }
                if (string.IsNullOrEmpty(s.Name)) Error(P(path, "name"), "must be a non-empty name");
                else if (names.TryGetValue(s.Name, out string? at)) Error(P(path, "name"), $"duplicate soft body name '{s.Name}' (first used at {at})");
                else names.Add(s.Name, path);

                string mesh = P(path, "mesh");
                if (s.Mesh == null) Error(mesh, "missing required field");
                else SoftMesh(s.Mesh, mesh);
                SoftMaterial(s.Material, P(path, "material"));
                Coordinate(s.Position, P(path, "position"));
                Rotation(s.Rotation, P(path, "rotation"));
                Speed(s.Velocity, P(path, "velocity"));
                SoftSettings(s, path);
                for (int i = 0; i < s.Pinned.Count; i++)
                {
                    ScenePin pin = s.Pinned[i];
                    string pp = JsonPath.Index(P(path, "pinned"), i);
                    if (Finite(pin.Min, P(pp, "min")) && Finite(pin.Max, P(pp, "max"))
                        && (pin.Max.X < pin.Min.X || pin.Max.Y < pin.Min.Y || pin.Max.Z < pin.Min.Z))
                        Error(P(pp, "max"), $"must be >= min on every axis, got min {V(pin.Min)} and max {V(pin.Max)}");
                    if (pin.To != null && !Exists(pin.To, bodies)) Error(P(pp, "to"), $"no body named '{pin.To}'");
                }
                string f = P(path, "initialDeformation");
                if (!s.InitialDeformation.IsFinite) Error(f, "must be finite");
                else if (s.InitialDeformation.Determinant == 0) Error(f, "must be invertible (its determinant is 0)");
                for (int i = 0; i < s.Probes.Count; i++) Finite(s.Probes[i], JsonPath.Index(P(path, "probes"), i));
                if (s.Plasticity is ScenePlasticity pl)
                {
                    string pp = P(path, "plasticity");
                    if (s.Mesh != null && s.Mesh.IsShell) Error(pp, $"needs a volume mesh; a {SceneNames.Of(s.Mesh.Type)} mesh is a triangle shell");
                    NonNegative(pl.YieldStrain, P(pp, "yieldStrain"));
                    Positive(pl.FlowRate, P(pp, "flowRate"));
                    Positive(pl.MaxStrain, P(pp, "maxStrain"));
                }
            }

            // The solver and contact settings; each is optional (null: the engine's default).
            void SoftSettings(SceneSoftBody s, string path)
            {
                if (s.Substeps is int substeps) IntInRange(substeps, 0, 1000, P(path, "substeps"));
                if (s.Iterations is int iterations) IntInRange(iterations, 1, 1000, P(path, "iterations"));
                if (s.DampingTime is float dampingTime) NonNegative(dampingTime, P(path, "dampingTime"));
                if (s.Solver == "newton" && s.Mesh?.Type == SceneSoftMeshType.Cloth)
                    Error(P(path, "solver"), "newton solves tetrahedra; a cloth (shell) mesh needs xpbd");
                if (s.LinearDamping is float linearDamping) NonNegative(linearDamping, P(path, "linearDamping"));
                if (s.GravityScale is float gravityScale) Finite(gravityScale, P(path, "gravityScale"));
                if (s.Friction is float friction) NonNegative(friction, P(path, "friction"));
                if (s.CollisionRadius is float radius) NonNegative(radius, P(path, "collisionRadius"));
                if (s.Layer is int layer) IntInRange(layer, 0, 31, P(path, "layer"));
                if (s.CollidesWith is int[] layers)
                    for (int i = 0; i < layers.Length; i++) IntInRange(layers[i], 0, 31, JsonPath.Index(P(path, "collidesWith"), i));
            }

            void SoftMesh(SceneSoftMesh m, string path)
            {
                string cells = P(path, "cells");
                switch (m)
                {
                    case SceneSoftBox box:
                        Positive(box.Size, P(path, "size"));
                        if (box.Cells == null || box.Cells.Length != 3) Error(cells, "must be [nx, ny, nz]");
                        else
                        {
                            bool ok = true;
                            for (int a = 0; a < 3; a++) ok &= AtLeast(box.Cells[a], 1, JsonPath.Index(cells, a));
                            if (ok && (long)box.Cells[0] * box.Cells[1] * box.Cells[2] > MaxBodies)
                                Error(cells, $"more than {MaxBodies} cells");
                        }
                        break;
                    case SceneSoftSphere sphere:
                        Positive(sphere.Radius, P(path, "radius"));
                        GridCells(sphere.Cells, SceneSoftSphere.MinCells, cells, 3);
                        break;
                    case SceneSoftCapsule capsule:
                        Positive(capsule.Radius, P(path, "radius"));
                        NonNegative(capsule.HalfHeight, P(path, "halfHeight"));
                        GridCells(capsule.Cells, SceneSoftSphere.MinCells, cells, 3);
                        break;
                    case SceneSoftBeam beam:
                        Positive(beam.Length, P(path, "length"));
                        Positive(beam.Thickness, P(path, "thickness"));
                        GridCells(beam.Cells, 1, cells, 1);
                        break;
                    case SceneSoftCloth cloth:
                        Positive(cloth.Size.X, JsonPath.Index(P(path, "size"), 0));
                        Positive(cloth.Size.Y, JsonPath.Index(P(path, "size"), 1));
                        if (cloth.Cells == null || cloth.Cells.Length != 2) Error(cells, "must be [nx, nz]");
                        else
                        {
                            bool ok = GridCells(cloth.Cells[0], 1, JsonPath.Index(cells, 0), 1);
                            ok &= GridCells(cloth.Cells[1], 1, JsonPath.Index(cells, 1), 1);
                            if (ok && (long)cloth.Cells[0] * cloth.Cells[1] > MaxBodies) Error(cells, $"more than {MaxBodies} cells");
                        }
                        Positive(cloth.Thickness, P(path, "thickness"));
                        NonNegative(cloth.BendingScale, P(path, "bendingScale"));
                        break;
                    case SceneSoftTetGen tetgen:
                        FilePath(tetgen.Node, P(path, "node"));
                        FilePath(tetgen.Ele, P(path, "ele"));
                        break;
                    case SceneSoftSurface surface:
                        FilePath(surface.File, P(path, "file"));
                        if (surface.Resolution < SceneSoftSurface.MinResolution || surface.Resolution > SceneSoftSurface.MaxResolution)
                            Error(P(path, "resolution"), $"must be in [{SceneSoftSurface.MinResolution}, {SceneSoftSurface.MaxResolution}], got {surface.Resolution}");
                        break;
                    case SceneSoftObj obj:
                        FilePath(obj.File, P(path, "file"));
                        Positive(obj.Thickness, P(path, "thickness"));
                        NonNegative(obj.BendingScale, P(path, "bendingScale"));
                        break;
                }
            }

            // Cells along one grid axis, in [min, MaxGridCells]; the grid (of the given dimension) stays within MaxBodies cells.
            bool GridCells(int n, int min, string path, int dimension)
            {
                if (n < min || n > MaxGridCells) { Error(path, $"must be in [{min}, {MaxGridCells}], got {n}"); return false; }
                long total = 1;
                for (int k = 0; k < dimension; k++) total *= n;
                if (total > MaxBodies) { Error(path, $"more than {MaxBodies} cells ({n}^{dimension})"); return false; }
                return true;
            }

            void FilePath(string file, string path)
            {
                if (string.IsNullOrWhiteSpace(file)) Error(path, "must be a non-empty file path");
            }

            void SoftMaterial(SceneSoftMaterial? m, string path)
            {
                if (m == null) { Error(path, "missing required field"); return; }
                bool engineering = m.YoungsModulus != null || m.PoissonRatio != null;
                bool lame = m.Mu != null || m.Lambda != null;
                if (engineering && lame) Error(path, "give youngsModulus and poissonRatio, or mu and lambda, not both");
                else if (!engineering && !lame) Error(path, "give youngsModulus and poissonRatio, or mu and lambda");
                else if (engineering)
                {
                    if (m.YoungsModulus is float e) Positive(e, P(path, "youngsModulus"));
                    else Error(P(path, "youngsModulus"), "missing: poissonRatio needs youngsModulus");
                    if (m.PoissonRatio is float nu)
                    {
                        if (!(nu > -1 && nu < 0.5f)) Error(P(path, "poissonRatio"), $"must be in (-1, 0.5), got {F(nu)}");
                    }
                    else Error(P(path, "poissonRatio"), "missing: youngsModulus needs poissonRatio");
                }
                else
                {
                    float mu = m.Mu ?? 0;
                    if (m.Mu == null) Error(P(path, "mu"), "missing: lambda needs mu");
                    else Positive(mu, P(path, "mu"));
                    if (m.Lambda is float lambda)
                    {
                        // A positive bulk modulus K = lambda + 2 mu / 3 keeps the material stable.
                        if (Finite(lambda, P(path, "lambda")) && m.Mu != null && !(lambda + 2f * mu / 3f > 0))
                            Error(P(path, "lambda"), $"must be > -2 mu / 3 (a positive bulk modulus), got {F(lambda)}");
                    }
                    else Error(P(path, "lambda"), "missing: mu needs lambda");
                }
                Positive(m.Density, P(path, "density"));
            }

            bool Finite(float v, string path)
            {
                if (float.IsFinite(v)) return true;
                Error(path, $"must be finite, got {F(v)}");
                return false;
            }

            bool Finite(Vector3 v, string path)
            {
                if (Mathematics.Validate.IsFinite(v)) return true;
                Error(path, $"must be finite, got {V(v)}");
                return false;
            }

            // The API's limits (see Limits), so that a scene the validator passes builds without an ArgumentException.
            void Coordinate(Vector3 v, string path) => Bounded(v, Limits.MaxPosition, path, "Limits.MaxPosition");

            void Extent(Vector3 v, string path) => Bounded(v, Limits.MaxShapeSize, path, "Limits.MaxShapeSize");

            void Bounded(Vector3 v, float max, string path, string limit)
            {
                if (!Finite(v, path)) return;
                if (System.Math.Abs(v.X) > max || System.Math.Abs(v.Y) > max || System.Math.Abs(v.Z) > max)
                    Error(path, $"must be within +-{F(max)} on every axis ({limit}), got {V(v)}");
            }

            void Speed(Vector3 v, string path)
            {
                if (Finite(v, path) && Limits.Length(v) > Limits.MaxInputSpeed)
                    Error(path, $"must have magnitude at most {F(Limits.MaxInputSpeed)} (Limits.MaxInputSpeed), got {V(v)}");
            }

            void Size(float v, string path)
            {
                if (Positive(v, path) && (v > Limits.MaxShapeSize || v < Limits.MinShapeSize))
                    Error(path, $"must be in [{F(Limits.MinShapeSize)}, {F(Limits.MaxShapeSize)}] m (Limits.MinShapeSize/MaxShapeSize), got {F(v)}");
            }

            void Size(Vector3 v, string path)
            {
                Positive(v, path);
                if (Mathematics.Validate.IsFinite(v) && v.X > 0 && v.Y > 0 && v.Z > 0
                    && (System.Math.Max(v.X, System.Math.Max(v.Y, v.Z)) > Limits.MaxShapeSize || System.Math.Min(v.X, System.Math.Min(v.Y, v.Z)) < Limits.MinShapeSize))
                    Error(path, $"must be in [{F(Limits.MinShapeSize)}, {F(Limits.MaxShapeSize)}] m on every axis (Limits.MinShapeSize/MaxShapeSize), got {V(v)}");
            }

            bool Positive(float v, string path)
            {
                if (float.IsFinite(v) && v > 0) return true;
                Error(path, $"must be > 0, got {F(v)}");
                return false;
            }

            void Positive(Vector3 v, string path)
            {
                if (Mathematics.Validate.IsFinite(v) && v.X > 0 && v.Y > 0 && v.Z > 0) return;
                Error(path, $"must be > 0 on every axis, got {V(v)}");
            }

            bool NonNegative(float v, string path)
            {
                if (float.IsFinite(v) && v >= 0) return true;
                Error(path, $"must be >= 0, got {F(v)}");
                return false;
            }

            // A value already known finite (and of the right sign) against a documented limit.
            void Upto(float v, float lo, float hi, string path, string limit)
            {
                if (v >= lo && v <= hi) return;
                Error(path, $"must be in [{F(lo)}, {F(hi)}] ({limit}), got {F(v)}");
            }

            void InRange(float v, float lo, float hi, string path)
            {
                if (float.IsFinite(v) && v >= lo && v <= hi) return;
                Error(path, $"must be in [{F(lo)}, {F(hi)}], got {F(v)}");
            }

            bool AtLeast(int v, int min, string path)
            {
                if (v >= min) return true;
                Error(path, $"must be >= {min}, got {v}");
                return false;
            }

            void IntInRange(int v, int lo, int hi, string path)
            {
                if (v < lo || v > hi) Error(path, $"must be in [{lo}, {hi}], got {v}");
            }

            void Axis(Vector3 v, string path)
            {
                if (Finite(v, path) && !(v.Length() > 1e-6f)) Error(path, "must be a non-zero direction");
            }

            void Rotation(Quaternion q, string path)
            {
                if (!Mathematics.Validate.IsFinite(q)) Error(path, "must be finite");
                else if (!(q.Length() > 1e-6f)) Error(path, "must be a non-zero quaternion [x, y, z, w]");
            }
        }
    }
}
