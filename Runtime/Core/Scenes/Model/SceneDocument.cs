using System.Collections.Generic;
using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// A scene file in memory: every field of the <c>fulcrum-scene/1</c> format (DESIGN.md,
    /// "The scene file") as plain, mutable data. Read one with <see cref="SceneFile.Parse"/>,
    /// check it with <see cref="SceneValidator"/>, save it with <see cref="SceneFile.Save(SceneDocument)"/>,
    /// turn it into a world with <see cref="SceneBuilder"/>. Units are SI, y is up.
    /// </summary>
    public sealed class SceneDocument
    {
        /// <summary>The only format tag this version reads and writes.</summary>
        public const string CurrentFormat = "fulcrum-scene/1";

        /// <summary><c>format</c>: must be <see cref="CurrentFormat"/>. Required.</summary>
        public string Format { get; set; } = CurrentFormat;

        /// <summary><c>gravity</c>, m/s^2. Default: (0, -9.81, 0).</summary>
        public Vector3 Gravity { get; set; } = new Vector3(0, -9.81f, 0);

        /// <summary><c>timestep</c>: the fixed step, seconds, &gt; 0. Default: 1/60 s.</summary>
        public float Timestep { get; set; } = 1f / 60f;

        /// <summary><c>solver</c>: solver kind, iterations and substeps.</summary>
        public SceneSolver Solver { get; set; } = new SceneSolver();

        /// <summary><c>materials</c>: named materials, in file order (the file writes them as one object).</summary>
        public List<SceneMaterial> Materials { get; } = new List<SceneMaterial>();

        /// <summary><c>bodies</c>: rigid bodies written out one by one.</summary>
        public List<SceneBody> Bodies { get; } = new List<SceneBody>();

        /// <summary><c>joints</c>: joints between named bodies (or a body and the world).</summary>
        public List<SceneJoint> Joints { get; } = new List<SceneJoint>();

        /// <summary><c>softBodies</c>: Neo-Hookean soft bodies.</summary>
        public List<SceneSoftBody> SoftBodies { get; } = new List<SceneSoftBody>();

        /// <summary><c>generators</c>: towers, pyramids, walls, piles, chains and dominoes that expand to bodies and joints.</summary>
        public List<SceneGenerator> Generators { get; } = new List<SceneGenerator>();

        /// <summary>The material called <paramref name="name"/>, or null.</summary>
        public SceneMaterial? FindMaterial(string? name)
        {
            if (name == null) return null;
            foreach (SceneMaterial m in Materials)
                if (m.Name == name) return m;
            return null;
        }

        /// <summary>
        /// The bodies and joints of the scene with every generator expanded: the written-out
        /// bodies and joints first, then each generator's in generator order.
        /// </summary>
        public SceneExpansion Expand() => SceneExpansion.Of(this);
    }
}
