using System.Collections.Generic;
using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// Turns a parsed JSON document into a <see cref="SceneDocument"/>, reporting structural
    /// problems (unknown fields, wrong types, missing required fields, unknown type names)
    /// at their paths. Value ranges and cross references are the <see cref="SceneValidator"/>'s.
    /// </summary>
    internal static class SceneReader
    {
        public static SceneDocument Read(JsonValue root, SceneDiagnostics d)
        {
            var doc = new SceneDocument();
            JsonObjectReader? r = JsonObjectReader.Open(root, d, "a scene object");
            if (r == null) return doc;
            doc.Format = r.String("format", required: true) ?? "";
            doc.Gravity = r.Vector("gravity", doc.Gravity);
            doc.Timestep = r.Float("timestep", doc.Timestep);
            if (r.Take("solver") is JsonValue solver) doc.Solver = ReadSolver(solver, d);
            if (r.Take("materials") is JsonValue materials) ReadMaterials(materials, doc.Materials, d);
            foreach (JsonValue b in r.Array("bodies"))
                if (ReadBody(b, d) is SceneBody body) doc.Bodies.Add(body);
            foreach (JsonValue j in r.Array("joints"))
                if (SceneJointReader.Read(j, d) is SceneJoint joint) doc.Joints.Add(joint);
            foreach (JsonValue s in r.Array("softBodies"))
                if (SceneSoftBodyReader.Read(s, d) is SceneSoftBody soft) doc.SoftBodies.Add(soft);
            foreach (JsonValue g in r.Array("generators"))
                if (SceneGeneratorReader.Read(g, d) is SceneGenerator generator) doc.Generators.Add(generator);
            r.Finish();
            return doc;
        }

        static SceneSolver ReadSolver(JsonValue v, SceneDiagnostics d)
        {
            var s = new SceneSolver();
            JsonObjectReader? r = JsonObjectReader.Open(v, d);
            if (r == null) return s;
            if (r.Name("type", SceneNames.SolverTypes, "solver", out SolverType t)) s.Type = t;
            s.Iterations = r.Int("iterations", s.Iterations);
            s.Substeps = r.Int("substeps", s.Substeps);
            s.ContactHertz = r.OptionalFloat("contactHertz");
            s.JointHertz = r.OptionalFloat("jointHertz");
            s.ManifoldReuse = r.OptionalFloat("manifoldReuse");
            s.ShockPropagation = r.OptionalBool("shockPropagation");
            s.ShockDepth = r.OptionalFloat("shockDepth");
            s.JointTrees = r.OptionalBool("jointTrees");
            s.MaxJointCorrectionSpeed = r.OptionalFloat("maxJointCorrectionSpeed");
            r.Finish();
            return s;
        }

        static void ReadMaterials(JsonValue v, List<SceneMaterial> into, SceneDiagnostics d)
        {
            if (v.Kind != JsonKind.Object)
            {
                d.Add(v.Path, $"expected an object of named materials, got {v.KindName}", v);
                return;
            }
            foreach (KeyValuePair<string, JsonValue> m in v.Members)
            {
                JsonObjectReader? r = JsonObjectReader.Open(m.Value, d);
                if (r == null) continue;
                var mat = new SceneMaterial { Name = m.Key };
                mat.Friction = r.Float("friction", mat.Friction);
                mat.Restitution = r.Float("restitution", mat.Restitution);
                mat.Density = r.OptionalFloat("density");
                r.Finish();
                into.Add(mat);
            }
        }

        static SceneBody? ReadBody(JsonValue v, SceneDiagnostics d)
        {
            JsonObjectReader? r = JsonObjectReader.Open(v, d, "a body object");
            if (r == null) return null;
            var b = new SceneBody { Name = r.String("name", required: true) ?? "" };
            if (r.Name("type", SceneNames.BodyTypes, "body type", out BodyType t)) b.Type = t;
            if (r.Take("shape", required: true) is JsonValue shape) b.Shape = ReadShape(shape, d);
            b.Mass = r.OptionalFloat("mass");
            b.Density = r.OptionalFloat("density");
            b.Material = r.String("material");
            b.Position = r.Vector("position", b.Position);
            b.Rotation = r.Rotation("rotation", b.Rotation);
            b.Velocity = r.Vector("velocity", b.Velocity);
            b.AngularVelocity = r.Vector("angularVelocity", b.AngularVelocity);
            b.Ccd = r.Bool("ccd", b.Ccd);
            b.LockAxes = ReadLockAxes(r.Array("lockAxes"), d);
            r.Finish();
            return b;
        }

        // "lockAxes": ["linearY", "angularX"]: each name once, each an axis of AxisLocks.
        static AxisLocks ReadLockAxes(IReadOnlyList<JsonValue> items, SceneDiagnostics d)
        {
            AxisLocks locks = AxisLocks.None;
            foreach (JsonValue item in items)
            {
                if (item.Kind != JsonKind.String)
                    d.Add(item.Path, $"expected an axis name ({SceneNames.Spellings(SceneNames.LockAxes)}), got {item.KindName}", item);
                else if (!SceneNames.TryParse(item.AsString, out AxisLocks axis))
                    d.Add(item.Path, $"unknown axis '{item.AsString}' (expected {SceneNames.Spellings(SceneNames.LockAxes)})", item);
                else if ((locks & axis) != 0)
                    d.Add(item.Path, $"axis '{item.AsString}' is listed twice", item);
                else locks |= axis;
            }
            return locks;
        }

        /// <summary>Reads a shape object; null (with errors) when its type is missing or unknown.</summary>
        public static SceneShape? ReadShape(JsonValue v, SceneDiagnostics d)
        {
            JsonObjectReader? r = JsonObjectReader.OpenTyped(v, d, "a shape object", SceneNames.ShapeTypes, "shape type", out SceneShapeType kind);
            if (r == null) return null;
            SceneShape shape;
            switch (kind)
            {
                case SceneShapeType.Sphere:
                    shape = new SceneSphere { Radius = r.Float("radius", 0, required: true) };
                    break;
                case SceneShapeType.Box:
                    shape = new SceneBox { HalfExtents = r.Vector("halfExtents", Vector3.Zero, required: true) };
                    break;
                case SceneShapeType.Capsule:
                    shape = new SceneCapsule { Radius = r.Float("radius", 0, required: true), HalfHeight = r.Float("halfHeight", 0, required: true) };
                    break;
                case SceneShapeType.Convex:
                {
                    var convex = new SceneConvex();
                    if (r.Vectors("points", required: true) is List<Vector3> points) convex.Points.AddRange(points);
                    shape = convex;
                    break;
                }
                case SceneShapeType.Plane:
                {
                    var plane = new ScenePlane();
                    plane.Normal = r.Vector("normal", plane.Normal);
                    plane.Offset = r.Float("offset", plane.Offset);
                    shape = plane;
                    break;
                }
                case SceneShapeType.Mesh:
                {
                    var mesh = new SceneMesh();
                    if (r.Vectors("vertices", required: true) is List<Vector3> vertices) mesh.Vertices.AddRange(vertices);
                    foreach (JsonValue t in r.Array("triangles", required: true))
                    {
                        if (t.Kind != JsonKind.Array || t.Items.Count != 3)
                        {
                            d.Add(t.Path, $"expected a triangle [i, j, k], got {JsonObjectReader.Describe(t)}", t);
                            continue;
                        }
                        for (int k = 0; k < 3; k++)
                            mesh.Triangles.Add(JsonObjectReader.ReadInt(t.Items[k], d, out int index) ? index : 0);
                    }
                    shape = mesh;
                    break;
                }
                default:
                {
                    var compound = new SceneCompound();
                    foreach (JsonValue c in r.Array("children", required: true))
                    {
                        JsonObjectReader? cr = JsonObjectReader.Open(c, d, "a child object {shape, position, rotation}");
                        if (cr == null) continue;
                        var child = new SceneCompoundChild();
                        if (cr.Take("shape", required: true) is JsonValue s) child.Shape = ReadShape(s, d);
                        child.Position = cr.Vector("position", child.Position);
                        child.Rotation = cr.Rotation("rotation", child.Rotation);
                        cr.Finish();
                        compound.Children.Add(child);
                    }
                    shape = compound;
                    break;
                }
            }
            r.Finish();
            return shape;
        }
    }
}
