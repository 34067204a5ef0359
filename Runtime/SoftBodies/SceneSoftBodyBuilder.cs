using System;
using System.IO;
using System.Numerics;
using Fulcrum.Scenes;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Creates the <c>softBodies</c> of a scene file in its world. Core keeps soft bodies as
    /// data (<see cref="SceneSoftBody"/>) so that a scene without them never loads this
    /// assembly; this is the other half. Rest coordinates of pins and probes are about the mesh
    /// centre, as DESIGN.md's scene format says.
    /// </summary>
    public static class SceneSoftBodyBuilder
    {
        /// <summary>
        /// Creates every soft body of <paramref name="scene"/>, in file order. A value the scene
        /// validator let through but the soft-body assembly refuses (a pin box that selects no
        /// vertex, say) throws a <see cref="SceneException"/> naming the JSON path; soft bodies
        /// created before it are destroyed again, so the world is left as it was.
        /// </summary>
        /// <param name="scene">The built scene.</param>
        /// <param name="substeps">XPBD substeps for every soft body; 0 keeps the automatic choice (one per 1/600 s).</param>
        /// <param name="iterations">XPBD iterations per substep; 0 keeps the default (1).</param>
        /// <param name="directory">The scene file's folder, against which <c>tetgen</c> and <c>obj</c> mesh paths resolve; null: the current directory.</param>
        public static SoftBodyHandle[] Build(SceneInstance scene, int substeps = 0, int iterations = 0, string? directory = null)
        {
            if (scene == null) throw new ArgumentNullException(nameof(scene));
            var handles = new SoftBodyHandle[scene.SoftBodies.Count];
            int made = 0;
            try
            {
                for (; made < handles.Length; made++)
                {
                    SoftBodyDef def = Definition(scene, made, directory);
                    if (substeps > 0) def.Substeps = substeps;
                    if (iterations > 0) def.Iterations = iterations;
                    handles[made] = scene.World.CreateSoftBody(def);
                }
            }
            catch (ArgumentException e)
            {
                for (int k = 0; k < made; k++) scene.World.DestroySoftBody(handles[k]);
                // The meshers name their fields as the scene does (mesh.radius, mesh.cells[0]).
                string path = $"$.softBodies[{made}]";
                if (e.ParamName is string field && (field == "mesh" || field.StartsWith("mesh.", StringComparison.Ordinal)))
                    path += "." + field;
                throw new SceneException(new[] { new SceneError(path, SceneError.MessageOf(e)) });
            }
            return handles;
        }

        /// <summary>
        /// The <see cref="SoftBodyDef"/> of soft body <paramref name="index"/> of the scene; mesh
        /// files (<c>tetgen</c>, <c>obj</c>) are read from <paramref name="directory"/> (null: the
        /// current directory). Throws an <see cref="ArgumentException"/> naming the field on a
        /// mesh the soft-body assembly refuses or a file it cannot read.
        /// </summary>
        public static SoftBodyDef Definition(SceneInstance scene, int index, string? directory = null)
        {
            SceneSoftBody s = scene.SoftBodies[index];
            SceneSoftMesh sceneMesh = s.Mesh ?? throw new ArgumentException("mesh is required.", "mesh");
            SceneSoftMaterial m = s.Material ?? throw new ArgumentException("material is required.", "material");
            MaterialModel model = m.Model == SceneSoftModel.NeoHookean ? MaterialModel.NeoHookean : MaterialModel.StableNeoHookean;
            NeoHookeanMaterial material = m.YoungsModulus is float e && m.PoissonRatio is float nu
                ? new NeoHookeanMaterial(model, e, nu, m.Density)
                : NeoHookeanMaterial.FromLame(model, m.Mu ?? 0, m.Lambda ?? 0, m.Density);

            SoftMesh mesh = MeshOf(sceneMesh, directory);
            // Generated meshes are centred on their origin; a file's mesh is moved so that the
            // scene's position, pins and probes are about its centre, as for every other kind.
            Vector3 centre = sceneMesh is SceneSoftTetGen || sceneMesh is SceneSoftObj || sceneMesh is SceneSoftSurface ? mesh.Center : Vector3.Zero;
            Quaternion rotation = Quaternion.Normalize(s.Rotation);
            SoftBodyDef def = SoftBodyDef.Of(mesh, material, s.Position - Vector3.Transform(centre, rotation));
            def.Name = s.Name;
            def.Rotation = rotation;
            def.LinearVelocity = s.Velocity;
            def.InitialDeformation = s.InitialDeformation;
            if (s.Substeps is int substeps) def.Substeps = substeps;
            if (s.Iterations is int iterations) def.Iterations = iterations;
            if (s.DampingTime is float dampingTime) def.DampingTime = dampingTime;
            if (s.Solver == "newton") def.Solver = SoftSolver.Newton;
            if (s.LinearDamping is float linearDamping) def.LinearDamping = linearDamping;
            if (s.GravityScale is float gravityScale) def.GravityScale = gravityScale;
            if (s.Friction is float friction) def.Friction = friction;
            if (s.CollisionRadius is float radius) def.CollisionRadius = radius;
            if (s.CollideWithShapes is bool shapes) def.CollideWithShapes = shapes;
            if (s.CollideWithSoftBodies is bool softBodies) def.CollideWithSoftBodies = softBodies;
            if (s.SelfCollision is bool self) def.SelfCollision = self;
            if (s.Layer is int layer) def.Layer = layer;
            if (s.CollidesWith is int[] layers)
            {
                uint mask = 0;
                for (int i = 0; i < layers.Length; i++) mask |= 1u << layers[i];
                def.CollidesWith = mask;
            }
            if (sceneMesh is SceneSoftCloth cloth)
            {
                def.Thickness = cloth.Thickness;
                def.BendingScale = cloth.BendingScale;
            }
            else if (sceneMesh is SceneSoftObj obj)
            {
                def.Thickness = obj.Thickness;
                def.BendingScale = obj.BendingScale;
            }
            if (s.Pinned.Count > 0)
            {
                def.Pins = new SoftPin[s.Pinned.Count];
                for (int p = 0; p < s.Pinned.Count; p++)
                {
                    ScenePin pin = s.Pinned[p];
                    def.Pins[p] = pin.To is string to
                        ? SoftPin.ToBody(pin.Min + centre, pin.Max + centre, scene.GetBody(to))
                        : SoftPin.ToWorld(pin.Min + centre, pin.Max + centre);
                }
            }
            if (s.Probes.Count > 0)
            {
                def.Probes = new Vector3[s.Probes.Count];
                for (int p = 0; p < s.Probes.Count; p++) def.Probes[p] = s.Probes[p] + centre;
            }
            if (s.Plasticity is ScenePlasticity flow) def.Plasticity = SoftPlasticity.Flow(flow.YieldStrain, flow.FlowRate, flow.MaxStrain);
            return def;
        }

        /// <summary>The engine mesh of a scene mesh; files are read relative to <paramref name="directory"/>.</summary>
        public static SoftMesh MeshOf(SceneSoftMesh mesh, string? directory = null)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            switch (mesh)
            {
                case SceneSoftBox box:
                    TetSplit split = box.Split == "five" ? TetSplit.Five : box.Split == "six-mirrored" ? TetSplit.SixMirrored : TetSplit.Six;
                    return SoftMesh.Box(box.Size, box.Cells[0], box.Cells[1], box.Cells[2], split);
                case SceneSoftSphere sphere: return SoftMesh.Sphere(sphere.Radius, sphere.Cells);
                case SceneSoftCapsule capsule: return SoftMesh.Capsule(capsule.Radius, capsule.HalfHeight, capsule.Cells);
                case SceneSoftBeam beam: return SoftMesh.Beam(beam.Length, beam.Thickness, beam.Cells);
                case SceneSoftCloth cloth: return SoftMesh.Cloth(cloth.Size.X, cloth.Size.Y, cloth.Cells[0], cloth.Cells[1]);
                case SceneSoftTetGen tetgen:
                {
                    string node = ReadText(directory, tetgen.Node, "mesh.node"), ele = ReadText(directory, tetgen.Ele, "mesh.ele");
                    try { return SoftMesh.FromTetGen(node, ele); }
                    catch (ArgumentException e)
                    {
                        // Name the file the reader's line number refers to.
                        bool inEle = e.Message.StartsWith("tetgen .ele", StringComparison.Ordinal);
                        throw new ArgumentException($"'{Scenes.SceneError.Clip(inEle ? tetgen.Ele : tetgen.Node, 200)}': {SceneError.MessageOf(e)}", inEle ? "mesh.ele" : "mesh.node", e);
                    }
                }
                case SceneSoftSurface surface:
                {
                    string text = ReadText(directory, surface.File, "mesh.file");
                    try
                    {
                        ObjReader.Read(text, out Vector3[] sv, out int[] st);
                        return SurfaceTetrahedralizer.Tetrahedralize(sv, st, surface.Resolution);
                    }
                    catch (ArgumentException e) when (e.ParamName != "mesh.resolution")
                    {
                        throw new ArgumentException($"'{Scenes.SceneError.Clip(surface.File, 200)}': {SceneError.MessageOf(e)}", "mesh.file", e);
                    }
                }
                case SceneSoftObj obj:
                {
                    string text = ReadText(directory, obj.File, "mesh.file");
                    try { return SoftMesh.FromObj(text); }
                    catch (ArgumentException e) { throw new ArgumentException($"'{Scenes.SceneError.Clip(obj.File, 200)}': {SceneError.MessageOf(e)}", "mesh.file", e); }
                }
                default: throw new ArgumentException($"mesh type {mesh.Type} is not supported.", "mesh.type");
            }
        }

        static string ReadText(string? directory, string file, string field)
        {
            string path = directory != null ? Path.Combine(directory, file) : file;
            try
            {
                return Scenes.SceneFile.ReadText(path);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is NotSupportedException || e is ArgumentException)
            {
                // SceneFile.ReadText's messages name the file already.
                throw new ArgumentException(e is IOException ? e.Message : $"cannot read '{Scenes.SceneError.Clip(path, 200)}': {e.Message}", field, e);
            }
        }
    }
}
