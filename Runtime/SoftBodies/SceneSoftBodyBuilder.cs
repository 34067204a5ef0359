using System;
using Fulcrum.Mathematics;
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
        public static SoftBodyHandle[] Build(SceneInstance scene, int substeps = 0, int iterations = 0)
        {
            if (scene == null) throw new ArgumentNullException(nameof(scene));
            var handles = new SoftBodyHandle[scene.SoftBodies.Count];
            int made = 0;
            try
            {
                for (; made < handles.Length; made++)
                {
                    SoftBodyDef def = Definition(scene, made);
                    if (substeps > 0) def.Substeps = substeps;
                    if (iterations > 0) def.Iterations = iterations;
                    handles[made] = scene.World.CreateSoftBody(def);
                }
            }
            catch (ArgumentException e)
            {
                for (int k = 0; k < made; k++) scene.World.DestroySoftBody(handles[k]);
                string path = $"$.softBodies[{made}]";
                throw new SceneException(new[] { new SceneError(path, e.Message) });
            }
            return handles;
        }

        /// <summary>The <see cref="SoftBodyDef"/> of soft body <paramref name="index"/> of the scene.</summary>
        public static SoftBodyDef Definition(SceneInstance scene, int index)
        {
            SceneSoftBody s = scene.SoftBodies[index];
            SceneSoftMesh mesh = s.Mesh ?? throw new ArgumentException("mesh is required.", "mesh");
            SceneSoftMaterial m = s.Material ?? throw new ArgumentException("material is required.", "material");
            MaterialModel model = m.Model == SceneSoftModel.NeoHookean ? MaterialModel.NeoHookean : MaterialModel.StableNeoHookean;
            NeoHookeanMaterial material = m.YoungsModulus is float e && m.PoissonRatio is float nu
                ? new NeoHookeanMaterial(model, e, nu, m.Density)
                : NeoHookeanMaterial.FromLame(model, m.Mu ?? 0, m.Lambda ?? 0, m.Density);

            SoftBodyDef def = SoftBodyDef.Of(SoftMesh.Box(mesh.Size, mesh.Cells[0], mesh.Cells[1], mesh.Cells[2]), material, s.Position);
            def.Name = s.Name;
            def.InitialDeformation = s.InitialDeformation;
            if (s.Pinned.Count > 0)
            {
                def.Pins = new SoftPin[s.Pinned.Count];
                for (int p = 0; p < s.Pinned.Count; p++)
                {
                    ScenePin pin = s.Pinned[p];
                    def.Pins[p] = pin.To is string to
                        ? SoftPin.ToBody(pin.Min, pin.Max, scene.GetBody(to))
                        : SoftPin.ToWorld(pin.Min, pin.Max);
                }
            }
            if (s.Probes.Count > 0) def.Probes = s.Probes.ToArray();
            if (s.Plasticity is ScenePlasticity flow) def.Plasticity = SoftPlasticity.Flow(flow.YieldStrain, flow.FlowRate, flow.MaxStrain);
            return def;
        }
    }
}
