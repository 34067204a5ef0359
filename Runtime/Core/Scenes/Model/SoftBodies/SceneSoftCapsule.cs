namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "capsule", "radius": r, "halfHeight": h, "cells": n}</c>: a capsule of
    /// tetrahedra along local y, carved from a grid of n cells across its diameter.
    /// </summary>
    public sealed class SceneSoftCapsule : SceneSoftMesh
    {
        /// <inheritdoc/>
        public override SceneSoftMeshType Type => SceneSoftMeshType.Capsule;

        /// <summary><c>radius</c>, m, &gt; 0. Required.</summary>
        public float Radius { get; set; }

        /// <summary><c>halfHeight</c>: half the length of the inner segment, m, &gt;= 0 (0 is a ball). Required.</summary>
        public float HalfHeight { get; set; }

        /// <summary><c>cells</c>: grid cells across the diameter, in [4, 1024]. Default: 6.</summary>
        public int Cells { get; set; } = SceneSoftSphere.DefaultCells;
    }
}
