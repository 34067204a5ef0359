using System;

namespace Fulcrum.Collision
{
    /// <summary>What <see cref="World.DebugDraw"/> puts in the buffer.</summary>
    [Flags]
    public enum DebugDrawFlags
    {
        /// <summary>Nothing.</summary>
        None = 0,
        /// <summary>Shape outlines (box and hull edges, three circles per sphere, capsule outlines, mesh triangles).</summary>
        Shapes = 1,
        /// <summary>Each shape's tight world bounds.</summary>
        ShapeBounds = 2,
        /// <summary>Every node of both broad-phase trees (leaves: fat bounds).</summary>
        TreeNodes = 4,
        /// <summary>Contact points of the last step, their normals (0.1 m) and depths.</summary>
        Contacts = 8,
        /// <summary>Everything.</summary>
        All = Shapes | ShapeBounds | TreeNodes | Contacts,
    }
}
