namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "sphere", "radius": r, "cells": n}</c>: a ball of tetrahedra carved from a grid
    /// of n cells along its diameter, surface vertices moved onto the sphere.
    /// </summary>
    public sealed class SceneSoftSphere : SceneSoftMesh
    {
        /// <summary>The default of <see cref="Cells"/>.</summary>
        public const int DefaultCells = 6;

        /// <summary>
        /// The fewest grid cells across a carved ball or capsule: 4. With 2 or 3, no tet's centroid
        /// lies far enough inside the surface to be kept, and the mesh came out empty.
        /// </summary>
        public const int MinCells = 4;

        /// <inheritdoc/>
        public override SceneSoftMeshType Type => SceneSoftMeshType.Sphere;

        /// <summary><c>radius</c>, m, &gt; 0. Required.</summary>
        public float Radius { get; set; }

        /// <summary><c>cells</c>: grid cells along the diameter, in [4, 1024]. Default: 6.</summary>
        public int Cells { get; set; } = DefaultCells;
    }
}
