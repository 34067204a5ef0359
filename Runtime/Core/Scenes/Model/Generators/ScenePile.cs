using System;
using System.Collections.Generic;
using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "pile", "grid": [nx, ny, nz], "shape": "box", "size": [1, 1, 1], "at": [0, 0, 0], "spacing": 0.1}</c>:
    /// a grid pile: nx x nz bodies per layer, ny layers, each body filling a cell of
    /// <c>size</c> (world axes) with <c>spacing</c> between cells on every axis (so the layers
    /// above start apart and fall into a pile). The bottom layer rests on y = at.y, centred on
    /// <c>at</c>. <c>shape</c> is <c>"box"</c> (the cell), <c>"sphere"</c> (radius = the
    /// smallest half-size) or <c>"capsule"</c> (upright: radius = the smallest half-size,
    /// half-height = size.y / 2 - radius). Bodies are numbered layer by layer from the bottom,
    /// then by z, then by x.
    /// </summary>
    public sealed class ScenePile : SceneGenerator
    {
        /// <summary>A pile of 1 m boxes with 0.1 m spacing.</summary>
        public ScenePile() : base(Vector3.One, 0.1f) { }

        /// <inheritdoc/>
        public override SceneGeneratorType Type => SceneGeneratorType.Pile;

        /// <summary><c>grid</c>: bodies along x, y (layers) and z, each &gt;= 1. Required.</summary>
        public int[] Grid { get; set; } = { 1, 1, 1 };

        /// <summary><c>shape</c>: <see cref="SceneShapeType.Box"/>, <see cref="SceneShapeType.Sphere"/> or <see cref="SceneShapeType.Capsule"/>. Default: box.</summary>
        public SceneShapeType Shape { get; set; } = SceneShapeType.Box;

        /// <inheritdoc/>
        public override long BodyCount
        {
            get
            {
                if (Grid == null || Grid.Length != 3 || Grid[0] <= 0 || Grid[1] <= 0 || Grid[2] <= 0) return 0;
                // Three counts of up to 2^31 overflow a long: saturate instead (checked arithmetic).
                try { return checked((long)Grid[0] * Grid[1] * Grid[2]); }
                catch (System.OverflowException) { return long.MaxValue; }
            }
        }

        /// <summary>The shape of each body, fitted to a cell of <see cref="SceneGenerator.Size"/>.</summary>
        public SceneShape CellShape()
        {
            float r = 0.5f * MathF.Min(Size.X, MathF.Min(Size.Y, Size.Z));
            switch (Shape)
            {
                case SceneShapeType.Sphere: return new SceneSphere { Radius = r };
                case SceneShapeType.Capsule: return new SceneCapsule { Radius = r, HalfHeight = 0.5f * Size.Y - r };
                default: return BoxOf(Size);
            }
        }

        /// <inheritdoc/>
        public override void Expand(List<SceneBody> bodies, List<SceneJoint> joints)
        {
            int nx = Grid[0], ny = Grid[1], nz = Grid[2];
            Vector3 pitch = Size + new Vector3(Spacing);
            int index = 0;
            for (int iy = 0; iy < ny; iy++)
            for (int iz = 0; iz < nz; iz++)
            for (int ix = 0; ix < nx; ix++)
            {
                var p = new Vector3(
                    At.X + (ix - 0.5f * (nx - 1)) * pitch.X,
                    At.Y + 0.5f * Size.Y + iy * pitch.Y,
                    At.Z + (iz - 0.5f * (nz - 1)) * pitch.Z);
                bodies.Add(NewBody(index++, p, CellShape()));
            }
        }
    }
}
