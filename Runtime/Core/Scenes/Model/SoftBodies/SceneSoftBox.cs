using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary><c>{"type": "box", "size": [x, y, z], "cells": [nx, ny, nz]}</c>: a box of tetrahedra centred on its position.</summary>
    public sealed class SceneSoftBox : SceneSoftMesh
    {
        /// <inheritdoc/>
        public override SceneSoftMeshType Type => SceneSoftMeshType.Box;

        /// <summary><c>size</c>: full edge lengths of the box, m, each &gt; 0. Required.</summary>
        public Vector3 Size { get; set; }

        /// <summary><c>cells</c>: cells along x, y and z, each &gt;= 1. Default: [1, 1, 1].</summary>
        public int[] Cells { get; set; } = { 1, 1, 1 };

        /// <summary>
        /// <c>split</c>: how each cell is cut into tets: "six" (default: six tets around one
        /// diagonal, every cell alike), "six-mirrored" (the same, every other cell mirrored, so
        /// the mesh leans no way) or "five". Read as given; the builder maps it.
        /// </summary>
        public string Split { get; set; } = "six";
    }
}
