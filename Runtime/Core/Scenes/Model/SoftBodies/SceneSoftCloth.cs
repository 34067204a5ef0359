using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "cloth", "size": [x, z], "cells": [nx, nz], "thickness": t, "bendingScale": b}</c>:
    /// a rectangular triangle shell in the x-z plane (normal +y) centred on its position, each
    /// cell cut into two triangles.
    /// </summary>
    public sealed class SceneSoftCloth : SceneSoftMesh
    {
        /// <summary>The default of <see cref="Thickness"/>, m (the engine's default sheet).</summary>
        public const float DefaultThickness = 0.0005f;

        /// <inheritdoc/>
        public override SceneSoftMeshType Type => SceneSoftMeshType.Cloth;

        /// <summary><c>size</c>: edge lengths along x and z, m, each &gt; 0. Required.</summary>
        public Vector2 Size { get; set; }

        /// <summary><c>cells</c>: cells along x and z, each in [1, 1024]. Default: [1, 1].</summary>
        public int[] Cells { get; set; } = { 1, 1 };

        /// <summary>
        /// <c>thickness</c> of the sheet, m, &gt; 0: mass per area is density times thickness,
        /// bending rigidity E t^3 / 12 (1 - nu^2). Default: 0.0005.
        /// </summary>
        public float Thickness { get; set; } = DefaultThickness;

        /// <summary><c>bendingScale</c>: multiplies the physical bending rigidity, &gt;= 0 (0: no bending). Default: 1.</summary>
        public float BendingScale { get; set; } = 1f;
    }
}
