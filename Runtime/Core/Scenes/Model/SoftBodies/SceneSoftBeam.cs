namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "beam", "length": l, "thickness": t, "cells": n}</c>: a square bar of
    /// tetrahedra along x, n cells along its length and as many across as keep the cells
    /// closest to cubes (at least one).
    /// </summary>
    public sealed class SceneSoftBeam : SceneSoftMesh
    {
        /// <inheritdoc/>
        public override SceneSoftMeshType Type => SceneSoftMeshType.Beam;

        /// <summary><c>length</c> along x, m, &gt; 0. Required.</summary>
        public float Length { get; set; }

        /// <summary><c>thickness</c>: the side of the square cross-section, m, &gt; 0. Required.</summary>
        public float Thickness { get; set; }

        /// <summary><c>cells</c>: cells along the length, in [1, 1024]. Default: 10.</summary>
        public int Cells { get; set; } = 10;
    }
}
