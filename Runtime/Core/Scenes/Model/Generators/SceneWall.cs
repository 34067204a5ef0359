using System.Collections.Generic;
using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "wall", "count": n, "rows": r, "size": [1, 0.5, 0.5], "axis": "x", "staggered": true, "at": [0, 0, 0], "spacing": 0}</c>:
    /// a brick wall along <c>axis</c>, <c>rows</c> rows high, the bottom row of <c>count</c>
    /// bricks centred on <c>at</c> and resting on y = at.y. With <c>staggered</c> (the default)
    /// every second row has <c>count - 1</c> bricks shifted by half a brick (a running bond),
    /// so count must then be &gt;= 2. <c>size</c> is [along, up, across]; <c>spacing</c> is the
    /// gap between bricks in a row. Bodies are numbered row by row from the bottom.
    /// </summary>
    public sealed class SceneWall : SceneGenerator
    {
        /// <summary>A wall of 1 x 0.5 x 0.5 bricks, spacing 0, along x, staggered.</summary>
        public SceneWall() : base(new Vector3(1f, 0.5f, 0.5f), 0f) { }

        /// <inheritdoc/>
        public override SceneGeneratorType Type => SceneGeneratorType.Wall;

        /// <summary><c>count</c>: bricks in the bottom row, &gt;= 1 (&gt;= 2 when staggered). Required.</summary>
        public int Count { get; set; }

        /// <summary><c>rows</c>: number of rows, &gt;= 1. Required.</summary>
        public int Rows { get; set; }

        /// <summary><c>axis</c>: the direction of the rows. Default: x.</summary>
        public SceneAxis Axis { get; set; }

        /// <summary><c>staggered</c>: odd rows hold count - 1 bricks offset by half a brick. Default: true.</summary>
        public bool Staggered { get; set; } = true;

        int RowCount(int row) => Staggered && (row & 1) == 1 ? Count - 1 : Count;

        /// <inheritdoc/>
        public override long BodyCount
        {
            get
            {
                if (Rows <= 0 || Count <= 0) return 0;
                // Closed form (a loop over 2^31 rows takes seconds): odd rows of a staggered wall hold one brick less.
                long n = (long)Rows * Count;
                return Staggered ? n - Rows / 2 : n;
            }
        }

        /// <inheritdoc/>
        public override void Expand(List<SceneBody> bodies, List<SceneJoint> joints)
        {
            int index = 0;
            for (int row = 0; row < Rows; row++) AddRow(bodies, Axis, row, RowCount(row), ref index);
        }
    }
}
