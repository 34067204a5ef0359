using System.Collections.Generic;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Scenes
{
    /// <summary>Reads one entry of <c>softBodies</c>.</summary>
    internal static class SceneSoftBodyReader
    {
        public static SceneSoftBody? Read(JsonValue v, SceneDiagnostics d)
        {
            JsonObjectReader? r = JsonObjectReader.Open(v, d, "a soft body object");
            if (r == null) return null;
            var s = new SceneSoftBody { Name = r.String("name", required: true) ?? "" };
            if (r.Take("mesh", required: true) is JsonValue mesh) s.Mesh = ReadMesh(mesh, d);
            if (r.Take("material", required: true) is JsonValue material) s.Material = ReadMaterial(material, d);
            s.Position = r.Vector("position", s.Position);
            s.Rotation = r.Rotation("rotation", s.Rotation);
            s.Velocity = r.Vector("velocity", s.Velocity);
            foreach (JsonValue p in r.Array("pinned"))
                if (ReadPin(p, d) is ScenePin pin) s.Pinned.Add(pin);
            if (r.Take("initialDeformation") is JsonValue f && ReadMatrix(f, d, out Mat3 m)) s.InitialDeformation = m;
            if (r.Vectors("probes") is List<Vector3> probes) s.Probes.AddRange(probes);
            s.Substeps = r.OptionalInt("substeps");
            s.Iterations = r.OptionalInt("iterations");
            s.DampingTime = r.OptionalFloat("dampingTime");
            if (r.OneOf("solver", "xpbd", "newton") is string solver) s.Solver = solver;
            s.LinearDamping = r.OptionalFloat("linearDamping");
            s.GravityScale = r.OptionalFloat("gravityScale");
            s.Friction = r.OptionalFloat("friction");
            s.CollisionRadius = r.OptionalFloat("collisionRadius");
            s.CollideWithShapes = r.OptionalBool("collideWithShapes");
            s.CollideWithSoftBodies = r.OptionalBool("collideWithSoftBodies");
            s.SelfCollision = r.OptionalBool("selfCollision");
            s.Layer = r.OptionalInt("layer");
            s.CollidesWith = r.IntList("collidesWith");
            if (r.Take("plasticity") is JsonValue plasticity) s.Plasticity = ReadPlasticity(plasticity, d);
            r.Finish();
            return s;
        }

        static ScenePlasticity? ReadPlasticity(JsonValue v, SceneDiagnostics d)
        {
            JsonObjectReader? r = JsonObjectReader.Open(v, d, "a plasticity object");
            if (r == null) return null;
            var p = new ScenePlasticity();
            p.YieldStrain = r.Float("yieldStrain", p.YieldStrain);
            p.FlowRate = r.Float("flowRate", p.FlowRate, required: true);
            p.MaxStrain = r.Float("maxStrain", p.MaxStrain);
            r.Finish();
            return p;
        }

        static SceneSoftMesh? ReadMesh(JsonValue v, SceneDiagnostics d)
        {
            JsonObjectReader? r = JsonObjectReader.OpenTyped(v, d, "a mesh object", SceneNames.SoftMeshTypes, "soft mesh type", out SceneSoftMeshType kind);
            if (r == null) return null;
            SceneSoftMesh mesh;
            switch (kind)
            {
                case SceneSoftMeshType.Box:
                    var box = new SceneSoftBox { Size = r.Vector("size", Vector3.Zero, required: true) };
                    if (r.Ints("cells", 3) is int[] cells) box.Cells = cells;
                    if (r.OneOf("split", "six", "six-mirrored", "five") is string split) box.Split = split;
                    mesh = box;
                    break;
                case SceneSoftMeshType.Sphere:
                    var sphere = new SceneSoftSphere { Radius = r.Float("radius", 0, required: true) };
                    sphere.Cells = r.Int("cells", sphere.Cells);
                    mesh = sphere;
                    break;
                case SceneSoftMeshType.Capsule:
                    var capsule = new SceneSoftCapsule
                    {
                        Radius = r.Float("radius", 0, required: true),
                        HalfHeight = r.Float("halfHeight", 0, required: true),
                    };
                    capsule.Cells = r.Int("cells", capsule.Cells);
                    mesh = capsule;
                    break;
                case SceneSoftMeshType.Beam:
                    var beam = new SceneSoftBeam
                    {
                        Length = r.Float("length", 0, required: true),
                        Thickness = r.Float("thickness", 0, required: true),
                    };
                    beam.Cells = r.Int("cells", beam.Cells);
                    mesh = beam;
                    break;
                case SceneSoftMeshType.Cloth:
                    var cloth = new SceneSoftCloth();
                    if (r.Take("size", required: true) is JsonValue size
                        && JsonObjectReader.ReadFloats(size, d, 2, "a size [x, z]", out float[] xz))
                        cloth.Size = new Vector2(xz[0], xz[1]);
                    if (r.Ints("cells", 2) is int[] grid) cloth.Cells = grid;
                    cloth.Thickness = r.Float("thickness", cloth.Thickness);
                    cloth.BendingScale = r.Float("bendingScale", cloth.BendingScale);
                    mesh = cloth;
                    break;
                case SceneSoftMeshType.TetGen:
                    mesh = new SceneSoftTetGen
                    {
                        Node = r.String("node", required: true) ?? "",
                        Ele = r.String("ele", required: true) ?? "",
                    };
                    break;
                case SceneSoftMeshType.Surface:
                    var surface = new SceneSoftSurface { File = r.String("file", required: true) ?? "" };
                    surface.Resolution = r.Int("resolution", surface.Resolution);
                    mesh = surface;
                    break;
                default:
                    var obj = new SceneSoftObj { File = r.String("file", required: true) ?? "" };
                    obj.Thickness = r.Float("thickness", obj.Thickness);
                    obj.BendingScale = r.Float("bendingScale", obj.BendingScale);
                    mesh = obj;
                    break;
            }
            r.Finish();
            return mesh;
        }

        static SceneSoftMaterial? ReadMaterial(JsonValue v, SceneDiagnostics d)
        {
            JsonObjectReader? r = JsonObjectReader.Open(v, d, "a material object");
            if (r == null) return null;
            var m = new SceneSoftMaterial();
            if (r.Name("model", SceneNames.SoftModels, "model", out SceneSoftModel model)) m.Model = model;
            m.YoungsModulus = r.OptionalFloat("youngsModulus");
            m.PoissonRatio = r.OptionalFloat("poissonRatio");
            m.Mu = r.OptionalFloat("mu");
            m.Lambda = r.OptionalFloat("lambda");
            m.Density = r.Float("density", m.Density);
            r.Finish();
            return m;
        }

        static ScenePin? ReadPin(JsonValue v, SceneDiagnostics d)
        {
            JsonObjectReader? r = JsonObjectReader.Open(v, d, "a pin object {min, max, to}");
            if (r == null) return null;
            var pin = new ScenePin
            {
                Min = r.Vector("min", Vector3.Zero, required: true),
                Max = r.Vector("max", Vector3.Zero, required: true),
                To = r.String("to"),
            };
            r.Finish();
            return pin;
        }

        // Rows [[a,b,c],[d,e,f],[g,h,i]], as a matrix is written on paper.
        static bool ReadMatrix(JsonValue v, SceneDiagnostics d, out Mat3 m)
        {
            m = Mat3.Identity;
            if (v.Kind != JsonKind.Array || v.Items.Count != 3)
            {
                d.Add(v.Path, $"expected a 3x3 matrix as three rows [[a,b,c],[d,e,f],[g,h,i]], got {JsonObjectReader.Describe(v)}", v);
                return false;
            }
            bool ok = JsonObjectReader.ReadVector(v.Items[0], d, out Vector3 r0);
            ok &= JsonObjectReader.ReadVector(v.Items[1], d, out Vector3 r1);
            ok &= JsonObjectReader.ReadVector(v.Items[2], d, out Vector3 r2);
            if (ok) m = Mat3.FromRows(r0, r1, r2);
            return ok;
        }
    }
}
