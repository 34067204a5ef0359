using System.Collections.Generic;
using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "tower", "count": n, "size": [1, 1, 1], "at": [0, 0, 0], "spacing": 0}</c>:
    /// <c>count</c> boxes of <c>size</c> (world axes) stacked straight up, the bottom one centred
    /// over <c>at</c> and resting on y = at.y, <c>spacing</c> the vertical gap between boxes
    /// (default 0: each box rests on the one below). Body 0 is the bottom box.
    /// </summary>
    public sealed class SceneTower : SceneGenerator
    {
        /// <summary>A tower with size [1, 1, 1] and spacing 0.</summary>
        public SceneTower() : base(Vector3.One, 0f) { }

        /// <inheritdoc/>
        public override SceneGeneratorType Type => SceneGeneratorType.Tower;

        /// <summary><c>count</c>: number of boxes, &gt;= 1. Required.</summary>
        public int Count { get; set; }

        /// <inheritdoc/>
        public override long BodyCount => Count;

        /// <inheritdoc/>
        public override void Expand(List<SceneBody> bodies, List<SceneJoint> joints)
        {
            for (int i = 0; i < Count; i++)
            {
                float y = At.Y + 0.5f * Size.Y + i * (Size.Y + Spacing);
                bodies.Add(NewBody(i, new Vector3(At.X, y, At.Z), BoxOf(Size)));
            }
        }
    }
}
