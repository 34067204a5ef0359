using System.Collections.Generic;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// Turns a <see cref="SceneDocument"/> back into JSON such that reading the text gives an
    /// equal document: floats are written with round-trip formatting ("R", invariant culture)
    /// and every field that differs from its default is written. The document-level fields and
    /// each body's name, type, shape and position are always written; other fields at their
    /// defaults are left out to keep saved files short. Defaults are compared bit for bit, so
    /// even -0 survives.
    /// </summary>
    internal static class SceneWriter
    {
        public static JsonValue Write(SceneDocument doc)
        {
            var o = new Obj();
            o.Add("format", doc.Format);
            o.Add("gravity", doc.Gravity);
            o.Add("timestep", doc.Timestep);
            var solver = new Obj()
                .Add("type", SceneNames.Of(doc.Solver.Type))
                .Add("iterations", doc.Solver.Iterations)
                .Add("substeps", doc.Solver.Substeps);
            solver.AddIfSet("contactHertz", doc.Solver.ContactHertz);
            solver.AddIfSet("jointHertz", doc.Solver.JointHertz);
            solver.AddIfSet("manifoldReuse", doc.Solver.ManifoldReuse);
            solver.AddIfSet("shockPropagation", doc.Solver.ShockPropagation);
            solver.AddIfSet("shockDepth", doc.Solver.ShockDepth);
            solver.AddIfSet("jointTrees", doc.Solver.JointTrees);
            solver.AddIfSet("maxJointCorrectionSpeed", doc.Solver.MaxJointCorrectionSpeed);
            o.Add("solver", solver.Value);
            if (doc.Materials.Count > 0)
            {
                var materials = new Obj();
                foreach (SceneMaterial m in doc.Materials)
                {
                    var mo = new Obj().Add("friction", m.Friction).Add("restitution", m.Restitution);
                    mo.AddIfSet("density", m.Density);
                    materials.Add(m.Name, mo.Value);
                }
                o.Add("materials", materials.Value);
            }
            if (doc.Bodies.Count > 0) o.Add("bodies", ListOf(doc.Bodies, Body));
            if (doc.Joints.Count > 0) o.Add("joints", ListOf(doc.Joints, Joint));
            if (doc.SoftBodies.Count > 0) o.Add("softBodies", ListOf(doc.SoftBodies, SoftBody));
            if (doc.Generators.Count > 0) o.Add("generators", ListOf(doc.Generators, Generator));
            return o.Value;
        }

        static JsonValue Body(SceneBody b)
        {
            var o = new Obj().Add("name", b.Name).Add("type", SceneNames.Of(b.Type));
            o.AddIfSet("mass", b.Mass);
            o.AddIfSet("density", b.Density);
            o.AddIfSet("material", b.Material);
            o.Add("shape", b.Shape != null ? Shape(b.Shape) : JsonValue.Null());
            o.Add("position", b.Position);
            o.AddUnless("rotation", b.Rotation, Quaternion.Identity);
            o.AddUnless("velocity", b.Velocity, Vector3.Zero);
            o.AddUnless("angularVelocity", b.AngularVelocity, Vector3.Zero);
            if (b.Ccd) o.Add("ccd", true);
            if (b.LockAxes != AxisLocks.None)
            {
                var axes = new List<JsonValue>();
                foreach ((AxisLocks axis, string name) in SceneNames.LockAxes)
                    if ((b.LockAxes & axis) != 0) axes.Add(JsonValue.From(name));
                o.Add("lockAxes", JsonValue.Array(axes));
            }
            return o.Value;
        }

        static JsonValue Shape(SceneShape s)
        {
            var o = new Obj().Add("type", SceneNames.Of(s.Type));
            switch (s)
            {
                case SceneSphere sphere: o.Add("radius", sphere.Radius); break;
                case SceneBox box: o.Add("halfExtents", box.HalfExtents); break;
                case SceneCapsule capsule: o.Add("radius", capsule.Radius).Add("halfHeight", capsule.HalfHeight); break;
                case SceneConvex convex: o.Add("points", Points(convex.Points)); break;
                case ScenePlane plane: o.Add("normal", plane.Normal).Add("offset", plane.Offset); break;
                case SceneMesh mesh:
                {
                    o.Add("vertices", Points(mesh.Vertices));
                    var triangles = new List<JsonValue>();
                    for (int i = 0; i + 2 < mesh.Triangles.Count; i += 3)
                        triangles.Add(JsonValue.Array(new List<JsonValue>
                        {
                            JsonValue.From(mesh.Triangles[i]), JsonValue.From(mesh.Triangles[i + 1]), JsonValue.From(mesh.Triangles[i + 2]),
                        }));
                    o.Add("triangles", JsonValue.Array(triangles));
                    break;
                }
                case SceneCompound compound:
                    o.Add("children", ListOf(compound.Children, c =>
                    {
                        var co = new Obj().Add("shape", c.Shape != null ? Shape(c.Shape) : JsonValue.Null()).Add("position", c.Position);
                        co.AddUnless("rotation", c.Rotation, Quaternion.Identity);
                        return co.Value;
                    }));
                    break;
            }
            return o.Value;
        }

        static JsonValue Joint(SceneJoint j)
        {
            var o = new Obj().Add("type", SceneNames.Of(j.Type));
            o.AddIfSet("name", j.Name);
            o.Add("bodyA", j.BodyA != null ? JsonValue.From(j.BodyA) : JsonValue.Null());
            o.Add("bodyB", j.BodyB != null ? JsonValue.From(j.BodyB) : JsonValue.Null());
            o.Add("anchorA", j.AnchorA).Add("anchorB", j.AnchorB);
            if (j is SceneAxisPairJoint axes) o.Add("axisA", axes.AxisA).Add("axisB", axes.AxisB);
            switch (j)
            {
                case SceneHingeJoint h:
                    o.AddIfSet("lowerDeg", h.LowerDeg);
                    o.AddIfSet("upperDeg", h.UpperDeg);
                    o.AddUnless("motorSpeed", h.MotorSpeed, 0);
                    o.AddUnless("maxMotorTorque", h.MaxMotorTorque, 0);
                    break;
                case SceneDistanceJoint d:
                    o.AddIfSet("minLength", d.MinLength);
                    o.AddIfSet("maxLength", d.MaxLength);
                    o.AddUnless("stiffnessHz", d.StiffnessHz, 0);
                    o.AddUnless("damping", d.Damping, 0);
                    break;
                case ScenePrismaticJoint p:
                    o.Add("axisA", p.AxisA);
                    o.AddIfSet("lower", p.Lower);
                    o.AddIfSet("upper", p.Upper);
                    break;
                case SceneConeTwistJoint c:
                    o.Add("coneDeg", c.ConeDeg).Add("twistDeg", c.TwistDeg);
                    break;
            }
            o.AddIfSet("breakForce", j.BreakForce);
            o.AddIfSet("breakTorque", j.BreakTorque);
            o.AddIfSet("frictionTorque", j.FrictionTorque);
            return o.Value;
        }

        static JsonValue SoftBody(SceneSoftBody s)
        {
            var o = new Obj().Add("name", s.Name);
            if (s.Mesh != null) o.Add("mesh", SoftMesh(s.Mesh));
            if (s.Material != null)
            {
                SceneSoftMaterial m = s.Material;
                var mo = new Obj().Add("model", SceneNames.Of(m.Model));
                mo.AddIfSet("youngsModulus", m.YoungsModulus);
                mo.AddIfSet("poissonRatio", m.PoissonRatio);
                mo.AddIfSet("mu", m.Mu);
                mo.AddIfSet("lambda", m.Lambda);
                mo.Add("density", m.Density);
                o.Add("material", mo.Value);
            }
            o.Add("position", s.Position);
            o.AddUnless("rotation", s.Rotation, Quaternion.Identity);
            o.AddUnless("velocity", s.Velocity, Vector3.Zero);
            if (s.Pinned.Count > 0)
                o.Add("pinned", ListOf(s.Pinned, p =>
                {
                    var po = new Obj().Add("min", p.Min).Add("max", p.Max);
                    po.AddIfSet("to", p.To);
                    return po.Value;
                }));
            if (!Same(s.InitialDeformation, Mat3.Identity))
            {
                Mat3 f = s.InitialDeformation;
                o.Add("initialDeformation", JsonValue.Array(new List<JsonValue> { Vec(f.R0), Vec(f.R1), Vec(f.R2) }));
            }
            if (s.Probes.Count > 0) o.Add("probes", Points(s.Probes));
            o.AddIfSet("substeps", s.Substeps);
            o.AddIfSet("iterations", s.Iterations);
            o.AddIfSet("dampingTime", s.DampingTime);
            o.AddIfSet("solver", s.Solver);
            o.AddIfSet("linearDamping", s.LinearDamping);
            o.AddIfSet("gravityScale", s.GravityScale);
            o.AddIfSet("friction", s.Friction);
            o.AddIfSet("collisionRadius", s.CollisionRadius);
            o.AddIfSet("collideWithShapes", s.CollideWithShapes);
            o.AddIfSet("collideWithSoftBodies", s.CollideWithSoftBodies);
            o.AddIfSet("selfCollision", s.SelfCollision);
            o.AddIfSet("layer", s.Layer);
            if (s.CollidesWith is int[] layers) o.Add("collidesWith", Ints(layers));
            if (s.Plasticity is ScenePlasticity pl)
                o.Add("plasticity", new Obj().Add("yieldStrain", pl.YieldStrain).Add("flowRate", pl.FlowRate).Add("maxStrain", pl.MaxStrain).Value);
            return o.Value;
        }

        static JsonValue SoftMesh(SceneSoftMesh mesh)
        {
            var o = new Obj().Add("type", SceneNames.Of(mesh.Type));
            switch (mesh)
            {
                case SceneSoftBox box:
                    o.Add("size", box.Size).Add("cells", Ints(box.Cells));
                    if (box.Split != "six") o.Add("split", box.Split);
                    break;
                case SceneSoftSphere sphere: o.Add("radius", sphere.Radius).Add("cells", sphere.Cells); break;
                case SceneSoftCapsule capsule: o.Add("radius", capsule.Radius).Add("halfHeight", capsule.HalfHeight).Add("cells", capsule.Cells); break;
                case SceneSoftBeam beam: o.Add("length", beam.Length).Add("thickness", beam.Thickness).Add("cells", beam.Cells); break;
                case SceneSoftCloth cloth:
                    o.Add("size", JsonValue.Array(new List<JsonValue> { JsonValue.From(cloth.Size.X), JsonValue.From(cloth.Size.Y) }))
                        .Add("cells", Ints(cloth.Cells)).Add("thickness", cloth.Thickness).Add("bendingScale", cloth.BendingScale);
                    break;
                case SceneSoftTetGen tetgen: o.Add("node", tetgen.Node).Add("ele", tetgen.Ele); break;
                case SceneSoftSurface surface: o.Add("file", surface.File).Add("resolution", surface.Resolution); break;
                case SceneSoftObj obj: o.Add("file", obj.File).Add("thickness", obj.Thickness).Add("bendingScale", obj.BendingScale); break;
            }
            return o.Value;
        }

        static JsonValue Generator(SceneGenerator g)
        {
            var o = new Obj().Add("type", SceneNames.Of(g.Type));
            o.AddIfSet("name", g.Name);
            switch (g)
            {
                case SceneTower t: o.Add("count", t.Count); break;
                case ScenePyramid p: o.Add("count", p.Count).Add("axis", SceneNames.Of(p.Axis)); break;
                case SceneWall w: o.Add("count", w.Count).Add("rows", w.Rows).Add("axis", SceneNames.Of(w.Axis)).Add("staggered", w.Staggered); break;
                case ScenePile pile: o.Add("grid", Ints(pile.Grid)).Add("shape", SceneNames.Of(pile.Shape)); break;
                case SceneChain c: o.Add("count", c.Count).Add("axis", SceneNames.Of(c.Axis)).Add("anchor", SceneNames.Of(c.Anchor)); break;
                case SceneDominoes d: o.Add("count", d.Count).Add("axis", SceneNames.Of(d.Axis)).Add("tipSpeed", d.TipSpeed); break;
            }
            o.Add("size", g.Size).Add("at", g.At).Add("spacing", g.Spacing);
            o.AddIfSet("mass", g.Mass);
            o.AddIfSet("material", g.Material);
            return o.Value;
        }

        static JsonValue ListOf<T>(List<T> items, System.Func<T, JsonValue> write)
        {
            var list = new List<JsonValue>(items.Count);
            foreach (T item in items) list.Add(write(item));
            return JsonValue.Array(list);
        }

        static JsonValue Points(List<Vector3> points)
        {
            var list = new List<JsonValue>(points.Count);
            foreach (Vector3 p in points) list.Add(Vec(p));
            return JsonValue.Array(list);
        }

        static JsonValue Ints(int[] values)
        {
            var list = new List<JsonValue>(values.Length);
            foreach (int v in values) list.Add(JsonValue.From(v));
            return JsonValue.Array(list);
        }

        static JsonValue Vec(Vector3 v) =>
            JsonValue.Array(new List<JsonValue> { JsonValue.From(v.X), JsonValue.From(v.Y), JsonValue.From(v.Z) });

        static bool Same(float a, float b) => System.BitConverter.SingleToInt32Bits(a) == System.BitConverter.SingleToInt32Bits(b);

        static bool Same(Vector3 a, Vector3 b) => Same(a.X, b.X) && Same(a.Y, b.Y) && Same(a.Z, b.Z);

        static bool Same(Quaternion a, Quaternion b) => Same(a.X, b.X) && Same(a.Y, b.Y) && Same(a.Z, b.Z) && Same(a.W, b.W);

        static bool Same(in Mat3 a, in Mat3 b) => Same(a.C0, b.C0) && Same(a.C1, b.C1) && Same(a.C2, b.C2);

        // A small builder for an object's members in order.
        sealed class Obj
        {
            readonly List<KeyValuePair<string, JsonValue>> _members = new List<KeyValuePair<string, JsonValue>>();

            public JsonValue Value => JsonValue.Object(_members);

            public Obj Add(string key, JsonValue v)
            {
                _members.Add(new KeyValuePair<string, JsonValue>(key, v));
                return this;
            }

            public Obj Add(string key, string v) => Add(key, JsonValue.From(v));

            public Obj Add(string key, float v) => Add(key, JsonValue.From(v));

            public Obj Add(string key, int v) => Add(key, JsonValue.From(v));

            public Obj Add(string key, bool v) => Add(key, JsonValue.From(v));

            public Obj Add(string key, Vector3 v) => Add(key, Vec(v));

            public Obj Add(string key, Quaternion q) =>
                Add(key, JsonValue.Array(new List<JsonValue> { JsonValue.From(q.X), JsonValue.From(q.Y), JsonValue.From(q.Z), JsonValue.From(q.W) }));

            // Optional fields: written only when present (null means "not in the file").
            public Obj AddIfSet(string key, float? v) => v is float f ? Add(key, f) : this;

            public Obj AddIfSet(string key, int? v) => v is int i ? Add(key, i) : this;

            public Obj AddIfSet(string key, bool? v) => v is bool b ? Add(key, b) : this;

            public Obj AddIfSet(string key, string? v) => v != null ? Add(key, v) : this;

            // Fields with a default: written only when they differ from it bit for bit (see Same).
            public Obj AddUnless(string key, float v, float fallback) => Same(v, fallback) ? this : Add(key, v);

            public Obj AddUnless(string key, Vector3 v, Vector3 fallback) => Same(v, fallback) ? this : Add(key, v);

            public Obj AddUnless(string key, Quaternion v, Quaternion fallback) => Same(v, fallback) ? this : Add(key, v);
        }
    }
}
