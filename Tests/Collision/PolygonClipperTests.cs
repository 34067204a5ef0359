using System;
using System.Numerics;
using Fulcrum.Collision;
using NUnit.Framework;

namespace Fulcrum.Tests.Collision
{
    public class PolygonClipperTests
    {
        // The unit square [-1, 1]^2 in z = 0 as the incident polygon.
        static int Square(Vector3[] pts, uint[] keys, uint[] segs)
        {
            pts[0] = new Vector3(1, 1, 0);
            pts[1] = new Vector3(-1, 1, 0);
            pts[2] = new Vector3(-1, -1, 0);
            pts[3] = new Vector3(1, -1, 0);
            for (uint k = 0; k < 4; k++) { keys[k] = k; segs[k] = k; }
            return 4;
        }

        static int ClipBy(int planes, Vector3[] pts, uint[] keys)
        {
            var segs = new uint[8];
            int count = Square(pts, keys, segs);
            // x <= 0.5, y <= 0.5, x >= -0.5 (and y >= -0.5 for four planes).
            var normals = new[] { Vector3.UnitX, Vector3.UnitY, -Vector3.UnitX, -Vector3.UnitY };
            var offsets = new[] { 0.5f, 0.5f, 0.5f, 0.5f };
            return PolygonClipper.Clip(pts, keys, segs, count, normals.AsSpan(0, planes), offsets.AsSpan(0, planes),
                new Vector3[8], new uint[8], new uint[8]);
        }

        [Test]
        public void An_odd_number_of_planes_leaves_the_result_in_the_callers_buffers()
        {
            var pts = new Vector3[8];
            var keys = new uint[8];
            int count = ClipBy(3, pts, keys);
            // The square cut to x in [-0.5, 0.5], y <= 0.5: four corners, all crossings.
            Assert.That(count, Is.EqualTo(4));
            float minY = float.MaxValue, maxY = float.MinValue, minX = float.MaxValue, maxX = float.MinValue;
            for (int i = 0; i < count; i++)
            {
                minX = MathF.Min(minX, pts[i].X); maxX = MathF.Max(maxX, pts[i].X);
                minY = MathF.Min(minY, pts[i].Y); maxY = MathF.Max(maxY, pts[i].Y);
                Assert.That(keys[i] & 0x8000u, Is.EqualTo(0x8000u), "every kept vertex is a crossing");
            }
            Assert.That(minX, Is.EqualTo(-0.5f).Within(1e-6f));
            Assert.That(maxX, Is.EqualTo(0.5f).Within(1e-6f));
            Assert.That(minY, Is.EqualTo(-1f).Within(1e-6f));
            Assert.That(maxY, Is.EqualTo(0.5f).Within(1e-6f));
        }

        [Test]
        public void An_even_number_of_planes_cuts_the_square_to_the_inner_square()
        {
            var pts = new Vector3[8];
            var keys = new uint[8];
            int count = ClipBy(4, pts, keys);
            Assert.That(count, Is.EqualTo(4));
            for (int i = 0; i < count; i++)
            {
                Assert.That(MathF.Abs(pts[i].X), Is.EqualTo(0.5f).Within(1e-6f));
                Assert.That(MathF.Abs(pts[i].Y), Is.EqualTo(0.5f).Within(1e-6f));
            }
        }
    }
}
