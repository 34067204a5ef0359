using System.Collections.Generic;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// A world built from a scene by <see cref="SceneBuilder"/>, with the map from body names
    /// to handles. Joints and soft bodies are carried as data (<see cref="Joints"/>,
    /// <see cref="SoftBodies"/>) until the world can create them.
    /// </summary>
    public sealed class SceneInstance
    {
        readonly Dictionary<string, BodyHandle> _byName;

        internal SceneInstance(World world, SceneDocument document, SceneExpansion expansion, List<BodyHandle> handles)
        {
            World = world;
            Document = document;
            Expansion = expansion;
            BodyHandles = handles;
            _byName = new Dictionary<string, BodyHandle>(handles.Count);
            for (int i = 0; i < handles.Count; i++) _byName.Add(expansion.Bodies[i].Name, handles[i]);
        }

        /// <summary>The world, ready to step.</summary>
        public World World { get; }

        /// <summary>The document the world was built from.</summary>
        public SceneDocument Document { get; }

        /// <summary>The document's bodies and joints with the generators expanded.</summary>
        public SceneExpansion Expansion { get; }

        /// <summary>The fixed step of the scene, seconds (<see cref="SceneDocument.Timestep"/>).</summary>
        public float Timestep => Document.Timestep;

        /// <summary>The handle of each body, in the order of <see cref="SceneExpansion.Bodies"/>.</summary>
        public IReadOnlyList<BodyHandle> BodyHandles { get; }

        /// <summary>The name of each body, in the order of <see cref="BodyHandles"/>.</summary>
        public string BodyName(int index) => Expansion.Bodies[index].Name;

        /// <summary>Body handles by name.</summary>
        public IReadOnlyDictionary<string, BodyHandle> Bodies => _byName;

        /// <summary>The handle of the body called <paramref name="name"/>; throws <see cref="KeyNotFoundException"/> naming it otherwise.</summary>
        public BodyHandle GetBody(string name) =>
            _byName.TryGetValue(name, out BodyHandle h) ? h : throw new KeyNotFoundException($"The scene has no body named '{name}'.");

        /// <summary>The scene's joints (written-out and generated) as data.</summary>
        public IReadOnlyList<SceneJoint> Joints => Expansion.Joints;

        /// <summary>Handles of the joints created in the world, parallel to <see cref="Joints"/>.</summary>
        public IReadOnlyList<JointHandle> JointHandles => _joints;

        readonly List<JointHandle> _joints = new List<JointHandle>();

        internal void AddJoint(JointHandle joint) => _joints.Add(joint);

        /// <summary>The scene's soft bodies as data, for Fulcrum.SoftBodies to create.</summary>
        public IReadOnlyList<SceneSoftBody> SoftBodies => Document.SoftBodies;
    }
}
