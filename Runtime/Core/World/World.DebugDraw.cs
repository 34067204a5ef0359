using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    public sealed partial class World
    {
        /// <summary>
        /// Appends debug geometry to <paramref name="buffer"/> (not cleared first): shape
        /// outlines, bounds, broad-phase tree nodes and the last step's contact points with
        /// their normals and depths, as selected by <paramref name="flags"/>. Call between
        /// steps, when something is to be drawn; a step never does this work.
        /// </summary>
        public void DebugDraw(DebugDrawBuffer buffer, DebugDrawFlags flags)
        {
            if (buffer == null) throw new ArgumentNullException(nameof(buffer));
            ThrowIfInStep();
            RefreshQueryBounds();
            ShapeStorage s = Shapes;
            if ((flags & (DebugDrawFlags.Shapes | DebugDrawFlags.ShapeBounds)) != 0)
                for (int k = 0; k < s.ActiveCount; k++)
                {
                    int i = s.Active[k];
                    if ((flags & DebugDrawFlags.Shapes) != 0) DrawShape(buffer, i);
                    if ((flags & DebugDrawFlags.ShapeBounds) != 0 && s.Geometry[i].Type != ShapeType.Plane)
                        buffer.AddBox(s.Geometry[i].ComputeAabb(ShapeWorldPose(i)), DebugColor.Bounds);
                }
            if ((flags & DebugDrawFlags.TreeNodes) != 0)
            {
                DrawTree(buffer, _broadPhase.StaticTree);
                DrawTree(buffer, _broadPhase.MovingTree);
            }
            if ((flags & DebugDrawFlags.Contacts) != 0) DrawContacts(buffer);
        }

        void DrawShape(DebugDrawBuffer buffer, int shape)
        {
            int body = Shapes.Body[shape];
            uint color = Bodies.Type[body] == BodyType.Static ? DebugColor.Static : Bodies.Awake[body] ? DebugColor.Awake : DebugColor.Asleep;
            ShapeGeometry g = Shapes.Geometry[shape];
            Pose pose = ShapeWorldPose(shape);
            Mat3 r = Mat3.FromQuaternion(pose.Rotation);
            switch (g.Type)
            {
                case ShapeType.Sphere:
                    buffer.AddCircle(pose.Position, r.C0, r.C1, g.Radius, color);
                    buffer.AddCircle(pose.Position, r.C1, r.C2, g.Radius, color);
                    buffer.AddCircle(pose.Position, r.C2, r.C0, g.Radius, color);
                    break;
                case ShapeType.Box:
                    buffer.AddOrientedBox(pose.Position, r, g.HalfExtents, color);
                    break;
                case ShapeType.Capsule:
                {
                    Vector3 top = pose.Position + r.C1 * g.HalfHeight, bottom = pose.Position - r.C1 * g.HalfHeight;
                    buffer.AddCircle(top, r.C0, r.C2, g.Radius, color);
                    buffer.AddCircle(bottom, r.C0, r.C2, g.Radius, color);
                    buffer.AddCircle(pose.Position, r.C0, r.C1, g.Radius, color, 8);
                    for (int k = 0; k < 4; k++)
                    {
                        Vector3 side = (k & 1) != 0 ? r.C0 : r.C2;
                        if ((k & 2) != 0) side = -side;
                        buffer.AddLine(top + side * g.Radius, bottom + side * g.Radius, color);
                    }
                    break;
                }
                case ShapeType.ConvexHull:
                {
                    var hull = (ConvexHull)g.Data!;
                    for (int e = 0; e < hull.EdgeCount; e++)
                        buffer.AddLine(pose.TransformPoint(hull.Vertices[hull.EdgeVertices[2 * e]]), pose.TransformPoint(hull.Vertices[hull.EdgeVertices[2 * e + 1]]), color);
                    break;
                }
                case ShapeType.TriangleMesh:
                {
                    var mesh = (TriangleMesh)g.Data!;
                    for (int t = 0; t < mesh.TriangleCount; t++)
                    {
                        mesh.GetTriangle(t, pose, out Vector3 a, out Vector3 b, out Vector3 c);
                        buffer.AddLine(a, b, color);
                        buffer.AddLine(b, c, color);
                        buffer.AddLine(c, a, color);
                    }
                    break;
                }
                case ShapeType.Plane:
                {
                    // A 10 m square of the plane around the point nearest the origin, and its normal.
                    Vector3 n = pose.TransformDirection(g.Normal);
                    Vector3 p = pose.TransformPoint(g.Normal * g.Offset);
                    Vector3 u = Vector3.Normalize(Vector3.Cross(n, MathF.Abs(n.X) < 0.9f ? Vector3.UnitX : Vector3.UnitY));
                    Vector3 v = Vector3.Cross(n, u);
                    for (int k = -5; k <= 5; k++)
                    {
                        buffer.AddLine(p + u * k - v * 5, p + u * k + v * 5, color);
                        buffer.AddLine(p + v * k - u * 5, p + v * k + u * 5, color);
                    }
                    buffer.AddLine(p, p + n, DebugColor.Normal);
                    break;
                }
            }
        }

        static void DrawTree(DebugDrawBuffer buffer, DynamicAabbTree tree)
        {
            if (tree.Root < 0) return;
            TreeNode[] nodes = tree.Nodes;
            var stack = new ScratchStack<int>(stackalloc int[64]);
            stack.Push(tree.Root);
            while (!stack.IsEmpty)
            {
                int id = stack.Pop();
                ref readonly TreeNode n = ref nodes[id];
                buffer.AddBox(n.Box, n.IsLeaf ? DebugColor.TreeLeaf : DebugColor.TreeNode);
                if (n.IsLeaf) continue;
                stack.Push(n.Child1);
                stack.Push(n.Child2);
            }
            stack.Dispose();
        }

        void DrawContacts(DebugDrawBuffer buffer)
        {
            ContactSet set = Contacts;
            for (int k = 0; k < set.ManifoldCount; k++)
            {
                ref ContactManifold m = ref set[k];
                for (int i = 0; i < m.PointCount; i++)
                {
                    ref ContactPoint p = ref ContactManifold.Point(ref m, i);
                    buffer.AddPoint(p.Position, 0.02f, p.Separation < 0 ? DebugColor.Penetrating : DebugColor.Speculative);
                    buffer.AddLine(p.Position, p.Position + m.Normal * 0.1f, DebugColor.Normal);
                    // The depth: from the point to where the other surface is, along the normal.
                    buffer.AddLine(p.Position - m.Normal * (0.5f * p.Separation), p.Position + m.Normal * (0.5f * p.Separation),
                        p.Separation < 0 ? DebugColor.Penetrating : DebugColor.Speculative);
                }
            }
        }
    }
}
