using System.Collections.Generic;
using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "chain", "count": n, "size": [1, 0.2, 0.2], "axis": "x", "anchor": "first", "at": [0, 0, 0], "spacing": 0}</c>:
    /// <c>count</c> box links laid end to end along <c>axis</c>, starting at <c>at</c> and
    /// resting on y = at.y, with <c>spacing</c> between links. <c>size</c> is [along, up,
    /// across]. Consecutive links are joined by ball joints at the middle of the gap between
    /// them, at mid-height; <c>anchor</c> also joints the start of the chain (at <c>at</c>) and,
    /// for <c>"both"</c>, its end to the world. Joints are named like bodies, numbered from
    /// the start of the chain: with anchor first, joint 0 holds link 0 to the world and joint
    /// i (i &gt;= 1) joins link i - 1 to link i.
    /// </summary>
    public sealed class SceneChain : SceneGenerator
    {
        /// <summary>A chain of 1 x 0.2 x 0.2 links, spacing 0, along x, anchored at its start.</summary>
        public SceneChain() : base(new Vector3(1f, 0.2f, 0.2f), 0f) { }

        /// <inheritdoc/>
        public override SceneGeneratorType Type => SceneGeneratorType.Chain;

        /// <summary><c>count</c>: number of links, &gt;= 1. Required.</summary>
        public int Count { get; set; }

        /// <summary><c>axis</c>: the direction the chain is laid out in. Default: x.</summary>
        public SceneAxis Axis { get; set; }

        /// <summary><c>anchor</c>: which ends are jointed to the world. Default: first.</summary>
        public SceneChainAnchor Anchor { get; set; } = SceneChainAnchor.First;

        /// <inheritdoc/>
        public override long BodyCount => Count;

        /// <summary>How many joints <see cref="Expand"/> makes.</summary>
        public int JointCount => Count - 1 + (Anchor == SceneChainAnchor.None ? 0 : Anchor == SceneChainAnchor.First ? 1 : 2);

        /// <inheritdoc/>
        public override void Expand(List<SceneBody> bodies, List<SceneJoint> joints)
        {
            Vector3 along = SceneAxisFrame.Along(Axis);
            Vector3 worldSize = SceneAxisFrame.ToWorld(Axis, Size);
            float pitch = Size.X + Spacing;
            float reach = 0.5f * pitch;           // from a link's centre to the joint beyond its end
            Vector3 up = new Vector3(0, 0.5f * Size.Y, 0);
            int first = bodies.Count;
            for (int i = 0; i < Count; i++)
                bodies.Add(NewBody(i, At + up + along * ((i + 0.5f) * pitch), BoxOf(worldSize)));

            int j = 0;
            if (Anchor != SceneChainAnchor.None)
                joints.Add(Joint(j++, bodies[first].Name, null, -along * reach, At + up));
            for (int i = 1; i < Count; i++)
                joints.Add(Joint(j++, bodies[first + i - 1].Name, bodies[first + i].Name, along * reach, -along * reach));
            if (Anchor == SceneChainAnchor.Both)
                joints.Add(Joint(j, bodies[first + Count - 1].Name, null, along * reach, At + up + along * (Count * pitch)));
        }

        SceneBallJoint Joint(int index, string bodyA, string? bodyB, Vector3 anchorA, Vector3 anchorB) => new SceneBallJoint
        {
            Name = ItemName(index),
            BodyA = bodyA,
            BodyB = bodyB,
            AnchorA = anchorA,
            AnchorB = anchorB,
        };
    }
}
