using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Plain lists of lines and points that any renderer can draw (Unity gizmos, an SVG
    /// writer, a test). Filled on request by <see cref="World.DebugDraw"/>, never by a step.
    /// Keep one and reuse it: after the first fill it grows no more for the same scene.
    /// </summary>
    public sealed class DebugDrawBuffer
    {
        DebugLine[] _lines = new DebugLine[256];
        DebugPoint[] _points = new DebugPoint[64];
        int _lineCount, _pointCount;

        /// <summary>The lines added since the last <see cref="Clear"/>.</summary>
        public ReadOnlySpan<DebugLine> Lines => new ReadOnlySpan<DebugLine>(_lines, 0, _lineCount);

        /// <summary>The points added since the last <see cref="Clear"/>.</summary>
        public ReadOnlySpan<DebugPoint> Points => new ReadOnlySpan<DebugPoint>(_points, 0, _pointCount);

        /// <summary>Empties both lists (keeps their memory).</summary>
        public void Clear()
        {
            _lineCount = 0;
            _pointCount = 0;
        }

        /// <summary>Adds a line.</summary>
        public void AddLine(Vector3 a, Vector3 b, uint color)
        {
            if (_lineCount == _lines.Length) Array.Resize(ref _lines, 2 * _lines.Length);
            _lines[_lineCount++] = new DebugLine { A = a, B = b, Color = color };
        }

        /// <summary>Adds a point.</summary>
        public void AddPoint(Vector3 p, float size, uint color)
        {
            if (_pointCount == _points.Length) Array.Resize(ref _points, 2 * _points.Length);
            _points[_pointCount++] = new DebugPoint { Position = p, Size = size, Color = color };
        }

        /// <summary>Adds the 12 edges of a box.</summary>
        public void AddBox(in Aabb box, uint color)
        {
            Vector3 c = box.Center, e = box.Extents;
            AddOrientedBox(c, Mat3.Identity, e, color);
        }

        /// <summary>Adds the 12 edges of an oriented box (centre, rotation columns, half-extents).</summary>
        public void AddOrientedBox(Vector3 center, in Mat3 axes, Vector3 half, uint color)
        {
            Vector3 x = axes.C0 * half.X, y = axes.C1 * half.Y, z = axes.C2 * half.Z;
            for (int i = 0; i < 4; i++)
            {
                Vector3 u = (i & 1) != 0 ? y : -y, v = (i & 2) != 0 ? z : -z;
                AddLine(center - x + u + v, center + x + u + v, color);
                Vector3 s = (i & 1) != 0 ? x : -x, t = (i & 2) != 0 ? z : -z;
                AddLine(center - y + s + t, center + y + s + t, color);
                Vector3 p = (i & 1) != 0 ? x : -x, q = (i & 2) != 0 ? y : -y;
                AddLine(center - z + p + q, center + z + p + q, color);
            }
        }

        /// <summary>Adds a circle of <paramref name="segments"/> lines in the plane spanned by unit vectors u and v.</summary>
        public void AddCircle(Vector3 center, Vector3 u, Vector3 v, float radius, uint color, int segments = 24)
        {
            Vector3 prev = center + u * radius;
            for (int i = 1; i <= segments; i++)
            {
                float a = 2 * MathF.PI * i / segments;
                Vector3 p = center + (u * MathF.Cos(a) + v * MathF.Sin(a)) * radius;
                AddLine(prev, p, color);
                prev = p;
            }
        }
    }
}
