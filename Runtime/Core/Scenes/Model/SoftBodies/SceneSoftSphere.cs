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

        /// <inheritdoc/>
        public override SceneSoftMeshType Type => SceneSoftMeshType.Sphere;

        /// <summary><c>radius</c>, m, &gt; 0. Required.</summary>
        public float Radius { get; set; }

        /// <summary><c>cells</c>: grid cells along the diameter, in [2, 1024]. Default: 6.</summary>
        public int Cells { get; set; } = DefaultCells;
    }
}
