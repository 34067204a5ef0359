using System.Collections.Generic;
using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "pyramid", "count": n, "size": [1, 1, 1], "axis": "x", "at": [0, 0, 0], "spacing": 0}</c>:
    /// a flat pyramid of boxes in the vertical plane along <c>axis</c>. The bottom row has
    /// <c>count</c> boxes centred on <c>at</c> and resting on y = at.y; each row above has one
    /// box fewer and sits on the row below, centred; n (n + 1) / 2 boxes in all. <c>size</c> is
    /// [along, up, across]; <c>spacing</c> is the gap between neighbours in a row (default 0).
    /// Bodies are numbered row by row from the bottom, each row in the +axis direction.
    /// </summary>
    public sealed class ScenePyramid : SceneGenerator
    {
        /// <summary>A pyramid with size [1, 1, 1] and spacing 0 along x.</summary>
        public ScenePyramid() : base(Vector3.One, 0f) { }

        /// <inheritdoc/>
        public override SceneGeneratorType Type => SceneGeneratorType.Pyramid;

        /// <summary><c>count</c>: boxes in the bottom row (and number of rows), &gt;= 1. Required.</summary>
        public int Count { get; set; }

        /// <summary><c>axis</c>: the direction of the rows. Default: x.</summary>
        public SceneAxis Axis { get; set; }

        /// <inheritdoc/>
        public override long BodyCount => Count <= 0 ? 0 : (long)Count * ((long)Count + 1) / 2; // in long: Count + 1 overflows int at 2^31 - 1

        /// <inheritdoc/>
        public override void Expand(List<SceneBody> bodies, List<SceneJoint> joints)
        {
            int index = 0;
            for (int row = 0; row < Count; row++) AddRow(bodies, Axis, row, Count - row, ref index);
        }
    }
}
