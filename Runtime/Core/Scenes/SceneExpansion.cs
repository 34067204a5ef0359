using System.Collections.Generic;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// A scene's bodies and joints with every generator expanded: the written-out ones first,
    /// then each generator's in generator order. <see cref="BodySources"/> and
    /// <see cref="JointSources"/> give, for each, the JSON path it came from (a body's own
    /// entry, or the generator's) so that later errors can point into the file.
    /// </summary>
    public sealed class SceneExpansion
    {
        SceneExpansion() { }

        /// <summary>All bodies. Generated bodies are new objects: editing them changes nothing in the document.</summary>
        public List<SceneBody> Bodies { get; } = new List<SceneBody>();

        /// <summary>All joints.</summary>
        public List<SceneJoint> Joints { get; } = new List<SceneJoint>();

        /// <summary>For each body, the path of its entry (<c>$.bodies[i]</c> or <c>$.generators[k]</c>).</summary>
        public List<string> BodySources { get; } = new List<string>();

        /// <summary>For each joint, the path of its entry (<c>$.joints[i]</c> or <c>$.generators[k]</c>).</summary>
        public List<string> JointSources { get; } = new List<string>();

        /// <summary>Expands <paramref name="doc"/> (which should be valid: see <see cref="SceneValidator"/>).</summary>
        public static SceneExpansion Of(SceneDocument doc)
        {
            var e = new SceneExpansion();
            for (int i = 0; i < doc.Bodies.Count; i++)
            {
                e.Bodies.Add(doc.Bodies[i]);
                e.BodySources.Add(JsonPath.Index("$.bodies", i));
            }
            for (int i = 0; i < doc.Joints.Count; i++)
            {
                e.Joints.Add(doc.Joints[i]);
                e.JointSources.Add(JsonPath.Index("$.joints", i));
            }
            for (int k = 0; k < doc.Generators.Count; k++)
            {
                string source = JsonPath.Index("$.generators", k);
                doc.Generators[k].Expand(e.Bodies, e.Joints);
                while (e.BodySources.Count < e.Bodies.Count) e.BodySources.Add(source);
                while (e.JointSources.Count < e.Joints.Count) e.JointSources.Add(source);
            }
            return e;
        }
    }
}
