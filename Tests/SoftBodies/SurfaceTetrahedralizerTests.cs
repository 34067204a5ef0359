using System;
using System.Collections.Generic;
using System.Numerics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftBodies
{
    public class SurfaceTetrahedralizerTests
    {
        // A closed surface of revolution sampled on a (u, v) grid: the point at (u, v) is
        // given by shape; rings 0 and `rings` are poles for a sphere, or wrap for a torus.
        static void Torus(float major, float minor, int segments, int sides, out Vector3[] v, out int[] t)
        {
            v = new Vector3[segments * sides];
            for (int i = 0; i < segments; i++)
                for (int j = 0; j < sides; j++)
                {
                    float u = 2 * MathF.PI * i / segments, w = 2 * MathF.PI * j / sides;
                    float r = major + minor * MathF.Cos(w);
                    v[i * sides + j] = new Vector3(r * MathF.Cos(u), minor * MathF.Sin(w), r * MathF.Sin(u));
                }
            var tris = new List<int>();
            for (int i = 0; i < segments; i++)
                for (int j = 0; j < sides; j++)
                {
                    int a = i * sides + j, b = ((i + 1) % segments) * sides + j, c = ((i + 1) % segments) * sides + (j + 1) % sides, d = i * sides + (j + 1) % sides;
                    tris.AddRange(new[] { a, b, c, a, c, d });
                }
            t = tris.ToArray();
        }

        static void Sphere(float radius, int rings, int segments, out Vector3[] v, out int[] t)
        {
            var verts = new List<Vector3> { new Vector3(0, radius, 0) };
            for (int i = 1; i < rings; i++)
                for (int j = 0; j < segments; j++)
                {
                    float th = MathF.PI * i / rings, ph = 2 * MathF.PI * j / segments;
                    verts.Add(radius * new Vector3(MathF.Sin(th) * MathF.Cos(ph), MathF.Cos(th), MathF.Sin(th) * MathF.Sin(ph)));
                }
            verts.Add(new Vector3(0, -radius, 0));
            int south = verts.Count - 1;
            var tris = new List<int>();
            int Ring(int i, int j) => 1 + (i - 1) * segments + (j % segments);
            for (int j = 0; j < segments; j++)
            {
                tris.AddRange(new[] { 0, Ring(1, j + 1), Ring(1, j) });
                tris.AddRange(new[] { south, Ring(rings - 1, j), Ring(rings - 1, j + 1) });
            }
            for (int i = 1; i < rings - 1; i++)
                for (int j = 0; j < segments; j++)
                    tris.AddRange(new[] { Ring(i, j), Ring(i, j + 1), Ring(i + 1, j + 1), Ring(i, j), Ring(i + 1, j + 1), Ring(i + 1, j) });
            v = verts.ToArray();
            t = tris.ToArray();
        }

        // Enclosed volume by the divergence theorem: sum of a . (b x c) / 6 over the triangles.
        static float SurfaceVolume(Vector3[] v, int[] t)
        {
            float s = 0;
            for (int k = 0; k < t.Length; k += 3) s += Vector3.Dot(v[t[k]], Vector3.Cross(v[t[k + 1]], v[t[k + 2]])) / 6f;
            return MathF.Abs(s);
        }

        static float TetVolume(SoftMesh mesh, out float minVolume)
        {
            ReadOnlySpan<int> t = mesh.Tetrahedra;
            ReadOnlySpan<Vector3> x = mesh.Vertices;
            float total = 0;
            minVolume = float.MaxValue;
            for (int k = 0; k < t.Length; k += 4)
            {
                float vol = Vector3.Dot(x[t[k + 1]] - x[t[k]], Vector3.Cross(x[t[k + 2]] - x[t[k]], x[t[k + 3]] - x[t[k]])) / 6f;
                total += vol;
                minVolume = MathF.Min(minVolume, vol);
            }
            return total;
        }

        // Smallest dihedral angle over all tets, degrees: the angle between the two faces at each
        // of the six edges, from the faces' inward normals (pi minus the angle between them).
        static float MinDihedralDegrees(SoftMesh mesh)
        {
            ReadOnlySpan<int> t = mesh.Tetrahedra;
            ReadOnlySpan<Vector3> x = mesh.Vertices;
            float worst = 180;
            Span<Vector3> p = stackalloc Vector3[4];
            Span<Vector3> n = stackalloc Vector3[4];
            for (int k = 0; k < t.Length; k += 4)
            {
                for (int q = 0; q < 4; q++) p[q] = x[t[k + q]];
                for (int q = 0; q < 4; q++)
                {
                    // Face opposite vertex q, normal pointing towards q.
                    Vector3 a = p[(q + 1) % 4], b = p[(q + 2) % 4], c = p[(q + 3) % 4];
                    Vector3 nn = Vector3.Normalize(Vector3.Cross(b - a, c - a));
                    if (Vector3.Dot(nn, p[q] - a) < 0) nn = -nn;
                    n[q] = nn;
                }
                for (int i = 0; i < 4; i++)
                    for (int j = i + 1; j < 4; j++)
                    {
                        float cos = Math.Clamp(-Vector3.Dot(n[i], n[j]), -1f, 1f);
                        worst = MathF.Min(worst, MathF.Acos(cos) * 180f / MathF.PI);
                    }
            }
            return worst;
        }

        [Test]
        public void SphereSurfaceGivesUninvertedTetsWithTheEnclosedVolume()
        {
            Sphere(1f, 16, 32, out Vector3[] v, out int[] t);
            SoftMesh mesh = SurfaceTetrahedralizer.Tetrahedralize(v, t, 8);
            float volume = TetVolume(mesh, out float minVolume);
            float target = SurfaceVolume(v, t);
            TestContext.Progress.WriteLine($"sphere: {mesh.TetrahedronCount} tets, volume {volume / target:F4} of surface, min dihedral {MinDihedralDegrees(mesh):F1} deg");
            Assert.That(minVolume, Is.GreaterThan(0f));
            Assert.That(volume, Is.EqualTo(target).Within(0.05f * target));
            Assert.That(MinDihedralDegrees(mesh), Is.GreaterThan(15f));
        }

        [Test]
        public void TorusKeepsItsHoleAndVolume()
        {
            Torus(1f, 0.4f, 32, 16, out Vector3[] v, out int[] t);
            SoftMesh mesh = SurfaceTetrahedralizer.Tetrahedralize(v, t, 14);
            float volume = TetVolume(mesh, out float minVolume);
            float target = SurfaceVolume(v, t);
            TestContext.Progress.WriteLine($"torus: {mesh.TetrahedronCount} tets, volume {volume / target:F4} of surface, min dihedral {MinDihedralDegrees(mesh):F1} deg");
            Assert.That(minVolume, Is.GreaterThan(0f));
            Assert.That(volume, Is.EqualTo(target).Within(0.08f * target));
            Assert.That(MinDihedralDegrees(mesh), Is.GreaterThan(15f));
            // The hole stays empty: no tet vertex lies within half the hole's radius of the axis.
            foreach (Vector3 p in mesh.Vertices)
                Assert.That(new Vector2(p.X, p.Z).Length(), Is.GreaterThan(0.3f));
        }

        [Test]
        public void WindingNumberIsOneInsideAndZeroOutside()
        {
            Torus(1f, 0.4f, 32, 16, out Vector3[] v, out int[] t);
            Assert.That(SurfaceTetrahedralizer.WindingNumber(v, t, new Vector3(1f, 0, 0)), Is.EqualTo(1f).Within(1e-3f));
            Assert.That(SurfaceTetrahedralizer.WindingNumber(v, t, Vector3.Zero), Is.EqualTo(0f).Within(1e-3f));
            Assert.That(SurfaceTetrahedralizer.WindingNumber(v, t, new Vector3(3f, 0, 0)), Is.EqualTo(0f).Within(1e-3f));
        }

        [Test]
        public void BadInputIsRejected()
        {
            Sphere(1f, 4, 8, out Vector3[] v, out int[] t);
            Assert.That(() => SurfaceTetrahedralizer.Tetrahedralize(v, t, 1), Throws.TypeOf<ArgumentOutOfRangeException>());
            Assert.That(() => SurfaceTetrahedralizer.Tetrahedralize(v, new[] { 0, 1 }, 8), Throws.ArgumentException);
            Assert.That(() => SurfaceTetrahedralizer.Tetrahedralize(v, new[] { 0, 1, 999 }, 8), Throws.ArgumentException);
        }

        [Test]
        public void EmbeddedRenderMeshFollowsAnAffineMotionExactlyWithoutAllocating()
        {
            Sphere(1f, 12, 24, out Vector3[] v, out int[] t);
            SoftMesh mesh = SurfaceTetrahedralizer.Tetrahedralize(v, t, 6);
            var embedding = new EmbeddedRenderMesh(mesh, v, t);
            // An affine map (stretch, shear, shift) is reproduced exactly by barycentric
            // interpolation, inside the tets or extrapolated from the nearest one.
            Vector3 Map(Vector3 p) => new Vector3(1.5f * p.X + 0.2f * p.Y, 0.8f * p.Y, p.Z + 0.1f * p.X) + new Vector3(0.3f, -1f, 2f);
            var moved = new Vector3[mesh.VertexCount];
            for (int i = 0; i < moved.Length; i++) moved[i] = Map(mesh.Vertices[i]);
            var outV = new Vector3[v.Length];
            var outN = new Vector3[v.Length];
            for (int k = 0; k < 5; k++) embedding.Update(moved, outV, outN);
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int k = 0; k < 100; k++) embedding.Update(moved, outV, outN);
            // Under a byte a call, where the smallest object is 24 B: nothing per call (one
            // constant 24 B object was seen once in the measured window, from the runtime).
            Assert.That(GC.GetAllocatedBytesForCurrentThread() - before, Is.LessThan(100));
            for (int i = 0; i < v.Length; i++)
            {
                Assert.That(Vector3.Distance(outV[i], Map(v[i])), Is.LessThan(1e-4f));
                Assert.That(outN[i].Length(), Is.EqualTo(1f).Within(1e-4f));
            }
            // Outward winding of the sphere: normals point away from the moved centre.
            Vector3 centre = Map(Vector3.Zero);
            for (int i = 0; i < v.Length; i++) Assert.That(Vector3.Dot(outN[i], outV[i] - centre), Is.GreaterThan(0f));
        }
    }
}