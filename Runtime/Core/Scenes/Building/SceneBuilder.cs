using System.Collections.Generic;
using Fulcrum.Mathematics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// Builds a <see cref="World"/> from a <see cref="SceneDocument"/>: world settings from
    /// gravity and solver, then every body (written-out and generated) with its shapes,
    /// material and mass, then every joint. Soft bodies are returned as data in the
    /// <see cref="SceneInstance"/> for Fulcrum.SoftBodies to create (SceneSoftBodyBuilder).
    /// </summary>
    public static class SceneBuilder
    {
        /// <summary>Builds the scene on <see cref="WorldSettings.Default"/>.</summary>
        public static SceneInstance Build(SceneDocument document) => Build(document, WorldSettings.Default);

        /// <summary>
        /// Builds the scene on <paramref name="settings"/>, whose gravity, solver, iterations
        /// and substeps the scene overrides (the rest, threads for example, are kept). Throws a
        /// <see cref="SceneException"/> naming the JSON path when the document is invalid or a
        /// hull, mesh or joint cannot be built; then no world is returned.
        /// </summary>
        public static SceneInstance Build(SceneDocument document, WorldSettings settings)
        {
            SceneValidator.ThrowIfInvalid(document);
            settings.Gravity = document.Gravity;
            settings.Solver = document.Solver.Type;
            settings.Iterations = document.Solver.Iterations;
            settings.Substeps = document.Solver.Substeps;
            if (document.Solver.ContactHertz is float contactHertz) settings.ContactHertz = contactHertz;
            if (document.Solver.JointHertz is float jointHertz) settings.JointHertz = jointHertz;
            if (document.Solver.ManifoldReuse is float reuse) settings.ManifoldReuseDistance = reuse;
            if (document.Solver.ShockPropagation is bool shock) settings.ShockPropagation = shock;
            if (document.Solver.JointTrees is bool trees) settings.JointTrees = trees;
            if (document.Solver.ShockDepth is float shockDepth) settings.ShockDepth = shockDepth;
            if (document.Solver.MaxJointCorrectionSpeed is float jointSpeed) settings.MaxJointCorrectionSpeed = jointSpeed;

            SceneExpansion e = document.Expand();
            // Every geometry first: an unsupported shape fails before a world exists.
            var shapes = new List<ShapeDef>[e.Bodies.Count];
            for (int i = 0; i < e.Bodies.Count; i++)
            {
                string path = e.BodySources[i].StartsWith("$.bodies", System.StringComparison.Ordinal)
                    ? JsonPath.Member(e.BodySources[i], "shape")
                    : e.BodySources[i];
                shapes[i] = ShapesOf(e.Bodies[i], document.FindMaterial(e.Bodies[i].Material), path);
            }

            var world = new World(settings);
            var handles = new List<BodyHandle>(e.Bodies.Count);
            for (int i = 0; i < e.Bodies.Count; i++)
            {
                SceneBody b = e.Bodies[i];
                BodyDef def = BodyDef.Default;
                def.Type = b.Type;
                def.Name = b.Name;
                def.Position = b.Position;
                def.Rotation = b.Rotation;
                def.LinearVelocity = b.Velocity;
                def.AngularVelocity = b.AngularVelocity;
                def.Mass = b.Mass ?? 0;
                def.Ccd = b.Ccd;
                def.Locks = b.LockAxes;
                try
                {
                    BodyHandle h = world.CreateBody(def);
                    foreach (ShapeDef shape in shapes[i]) world.AddShape(h, shape);
                    handles.Add(h);
                }
                catch (System.ArgumentException error)
                {
                    // A limit only the built body shows (its mass from density and size, a
                    // generated body beyond the world bounds): name the entry, never a stack trace.
                    throw new SceneException(new SceneError(e.BodySources[i], SceneError.MessageOf(error)));
                }
            }
            var instance = new SceneInstance(world, document, e, handles);
            for (int j = 0; j < e.Joints.Count; j++)
            {
                JointDef def = SceneJointFactory.Definition(e.Joints[j], name => name == null ? BodyHandle.None : instance.GetBody(name));
                try
                {
                    instance.AddJoint(world.CreateJoint(def));
                }
                catch (System.ArgumentException error)
                {
                    // Limits the validator cannot see (a body jointed to itself, say): name the entry.
                    throw new SceneException(new SceneError(e.JointSources[j], SceneError.MessageOf(error)));
                }
            }
            return instance;
        }

        static List<ShapeDef> ShapesOf(SceneBody body, SceneMaterial? material, string path)
        {
            var list = new List<ShapeDef>(1);
            ShapeDef template = ShapeDef.Default;
            if (material != null)
            {
                template.Friction = material.Friction;
                template.Restitution = material.Restitution;
                if (material.Density is float density) template.Density = density;
            }
            if (body.Density is float own) template.Density = own;
            if (body.Shape is SceneCompound compound)
            {
                for (int c = 0; c < compound.Children.Count; c++)
                {
                    SceneCompoundChild child = compound.Children[c];
                    string childPath = JsonPath.Member(JsonPath.Index(JsonPath.Member(path, "children"), c), "shape");
                    ShapeDef def = template;
                    def.Geometry = SceneGeometry.Create(child.Shape!, childPath);
                    def.LocalPose = new Pose(child.Position, child.Rotation);
                    list.Add(def);
                }
            }
            else
            {
                ShapeDef def = template;
                def.Geometry = SceneGeometry.Create(body.Shape!, path);
                list.Add(def);
            }
            return list;
        }
    }
}
