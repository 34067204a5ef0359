using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftBodies
{
    public class MeshTests
    {
        static float Volume(SoftMesh mesh)
        {
            float v = 0;
            ReadOnlySpan<int> t = mesh.Tetrahedra;
            ReadOnlySpan<Vector3> x = mesh.Vertices;
            for (int k = 0; k < t.Length; k += 4)
                v += Vector3.Dot(x[t[k + 1]] - x[t[k]], Vector3.Cross(x[t[k + 2]] - x[t[k]], x[t[k + 3]] - x[t[k]])) / 6f;
            return v;
        }

        // Divergence theorem: (1/3) sum over outward faces of x . n dA is the enclosed volume;
        // it comes out negative if any face is wound inward.
        static void Surface(SoftMesh mesh, out float area, out float enclosed)
        {
            area = 0;
            enclosed = 0;
            ReadOnlySpan<int> f = mesh.SurfaceTriangles;
            ReadOnlySpan<Vector3> x = mesh.Vertices;
            for (int k = 0; k < f.Length; k += 3)
            {
                Vector3 n = Vector3.Cross(x[f[k + 1]] - x[f[k]], x[f[k + 2]] - x[f[k]]);
                area += 0.5f * n.Length();
                enclosed += Vector3.Dot(x[f[k]], n) / 6f;
            }
        }

        [TestCase(TetSplit.Six, 6)]
        [TestCase(TetSplit.Five, 5)]
        [TestCase(TetSplit.SixMirrored, 6)]
        public void Box_is_split_into_positive_tets_that_fill_it(TetSplit split, int perCell)
        {
            SoftMesh mesh = SoftMesh.Box(new Vector3(1, 2, 3), 2, 3, 4, split);
            Assert.That(mesh.VertexCount, Is.EqualTo(3 * 4 * 5));
            Assert.That(mesh.TetrahedronCount, Is.EqualTo(24 * perCell));
            Assert.That(Volume(mesh), Is.EqualTo(6f).Within(1e-4f));
            Surface(mesh, out float area, out float enclosed);
            Assert.That(area, Is.EqualTo(22f).Within(1e-3f));
            Assert.That(enclosed, Is.EqualTo(6f).Within(1e-3f));
            Assert.That(mesh.SurfaceTriangles.Length / 3, Is.EqualTo(2 * 2 * (2 * 3 + 3 * 4 + 2 * 4)), "two triangles per boundary cell face: the faces match up inside");
            Assert.That(mesh.Center, Is.EqualTo(Vector3.Zero));
        }

        // Six leans: every tet of every cell holds the cell's (0,0,0)-(1,1,1) diagonal. Mirrored,
        // the edges along a diagonal direction come in all four directions equally.
        [TestCase(TetSplit.Six, false)]
        [TestCase(TetSplit.SixMirrored, true)]
        public void A_mirrored_split_has_its_cell_diagonals_in_every_direction(TetSplit split, bool balanced)
        {
            SoftMesh mesh = SoftMesh.Box(new Vector3(4), 4, 4, 4, split);
            var count = new Dictionary<Vector3, int>();
            var edges = new HashSet<(int, int)>();
            for (int t = 0; t < mesh.TetrahedronCount; t++)
                for (int p = 0; p < 4; p++)
                    for (int q = p + 1; q < 4; q++)
                    {
                        int a = mesh.Tetrahedra[4 * t + p], b = mesh.Tetrahedra[4 * t + q];
                        if (!edges.Add((Math.Min(a, b), Math.Max(a, b)))) continue;
                        Vector3 e = mesh.Vertices[b] - mesh.Vertices[a];
                        if (MathF.Abs(MathF.Abs(e.X) - 1) > 1e-4f || MathF.Abs(MathF.Abs(e.Y) - 1) > 1e-4f || MathF.Abs(MathF.Abs(e.Z) - 1) > 1e-4f) continue;
                        if (e.X < 0) e = -e; // a line, not a direction
                        Vector3 key = new Vector3(MathF.Sign(e.X), MathF.Sign(e.Y), MathF.Sign(e.Z));
                        count[key] = count.TryGetValue(key, out int c) ? c + 1 : 1;
                    }
            TestContext.Out.WriteLine($"{split}: " + string.Join(", ", count.Select(kv => $"{kv.Key} {kv.Value}")));
            Assert.That(count.Values.Sum(), Is.EqualTo(64), "one body diagonal a cell");
            if (balanced) Assert.That(count.Values, Has.Count.EqualTo(4).And.All.EqualTo(16));
            else Assert.That(count.Values, Has.Count.EqualTo(1));
        }

        [Test]
        public void Beam_keeps_its_cells_near_cubes()
        {
            SoftMesh beam = SoftMesh.Beam(2f, 0.2f, 20);
            Assert.That(beam.TetrahedronCount, Is.EqualTo(20 * 2 * 2 * 6));
            Assert.That(Volume(beam), Is.EqualTo(0.08f).Within(1e-5f));
        }

        [Test]
        public void Carved_sphere_approximates_the_ball()
        {
            SoftMesh ball = SoftMesh.Sphere(0.5f, 10);
            float exact = 4f / 3f * MathF.PI * 0.125f;
            Surface(ball, out float area, out float enclosed);
            TestContext.Out.WriteLine($"sphere: {ball.TetrahedronCount} tets, volume {Volume(ball):F4} vs {exact:F4}, area {area:F4} vs {MathF.PI:F4}");
            Assert.That(Volume(ball), Is.EqualTo(exact).Within(0.05f * exact));
            Assert.That(area, Is.LessThan(1.3f * MathF.PI), "surface vertices are snapped onto the sphere");
            Assert.That(enclosed, Is.EqualTo(Volume(ball)).Within(1e-3f));
            Assert.That(ball.Bounds.Max.X, Is.EqualTo(0.5f).Within(0.01f));
        }

        [Test]
        public void Carved_capsule_approximates_the_capsule()
        {
            SoftMesh capsule = SoftMesh.Capsule(0.2f, 0.3f, 8);
            float exact = MathF.PI * 0.04f * 0.6f + 4f / 3f * MathF.PI * 0.008f;
            Assert.That(Volume(capsule), Is.EqualTo(exact).Within(0.06f * exact));
            Assert.That(capsule.Bounds.Max.Y, Is.EqualTo(0.5f).Within(0.01f));
        }

        // With fewer than four cells across, carving keeps no tet (no centroid lies a quarter
        // cell inside the surface): the factories used to accept 2 and 3 and then fail with
        // "mesh has no vertices", naming neither the parameter nor the limit. Four carves a mesh
        // for any radius and segment length.
        [TestCase(2)]
        [TestCase(3)]
        public void A_ball_or_capsule_of_too_few_cells_is_refused_by_its_cell_count(int cells)
        {
            var sphere = Assert.Throws<ArgumentException>(() => SoftMesh.Sphere(0.3f, cells))!;
            var capsule = Assert.Throws<ArgumentException>(() => SoftMesh.Capsule(0.1f, 0.4f, cells))!;
            Assert.That(sphere.ParamName, Is.EqualTo("mesh.cells"));
            Assert.That(sphere.Message, Does.Contain(">= 4"));
            Assert.That(capsule.ParamName, Is.EqualTo("mesh.cells"));
            foreach (float radius in new[] { 0.01f, 0.3f, 5f })
            {
                Assert.That(SoftMesh.Sphere(radius, 4).TetrahedronCount, Is.GreaterThan(0));
                Assert.That(SoftMesh.Capsule(radius, 3 * radius, 4).TetrahedronCount, Is.GreaterThan(0));
                Assert.That(SoftMesh.Capsule(radius, 0, 4).TetrahedronCount, Is.GreaterThan(0));
            }
        }

        [Test]
        public void TetGen_files_are_read_with_either_index_base_and_orientation()
        {
            // A unit cube cut into five tets, written 1-based and wound the other way round.
            const string node = "# unit cube\n8 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 1 1 0\n5 0 0 1\n6 1 0 1\n7 0 1 1\n8 1 1 1\n";
            const string ele = "5 4 0\n1 1 4 6 7\n2 2 1 4 6\n3 3 1 7 4\n4 5 1 6 7\n5 8 4 7 6\n";
            SoftMesh mesh = SoftMesh.FromTetGen(node, ele);
            Assert.That(mesh.TetrahedronCount, Is.EqualTo(5));
            Assert.That(Volume(mesh), Is.EqualTo(1f).Within(1e-5f));
            Surface(mesh, out float area, out _);
            Assert.That(area, Is.EqualTo(6f).Within(1e-4f));
        }

        [Test]
        public void Bad_TetGen_text_names_the_line()
        {
            var ex = Assert.Throws<ArgumentException>(() => SoftMesh.FromTetGen("2 3 0 0\n0 0 0 0\n1 1 0 0\n", "1 4 0\n0 0 1 2 3\n"));
            Assert.That(ex!.Message, Does.Contain("node 2 does not exist"));
            ex = Assert.Throws<ArgumentException>(() => SoftMesh.FromTetGen("3 3 0 0\n0 0 0 0\n1 1 0 0\n2 1 x 0\n", "1 4 0\n0 0 1 2 3\n"));
            Assert.That(ex!.Message, Does.Contain("line 4"));
        }

        [Test]
        public void Obj_surface_is_triangulated()
        {
            const string obj = "# cube\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nvn 0 0 1\n" +
                "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2/1/1 3/1/1 7/1/1 6/1/1\nf 3 4 8 7\nf -4 -1 -5 -8\n";
            SoftMesh mesh = SoftMesh.FromObj(obj);
            Assert.That(mesh.IsShell, Is.True);
            Assert.That(mesh.VertexCount, Is.EqualTo(8));
            Assert.That(mesh.TriangleCount, Is.EqualTo(12));
            Surface(mesh, out float area, out float enclosed);
            Assert.That(area, Is.EqualTo(6f).Within(1e-5f));
            Assert.That(MathF.Abs(enclosed), Is.EqualTo(1f).Within(1e-5f));
        }

        [Test]
        public void Cloth_grid_has_the_expected_triangles()
        {
            SoftMesh cloth = SoftMesh.Cloth(2f, 1f, 8, 4);
            Assert.That(cloth.VertexCount, Is.EqualTo(9 * 5));
            Assert.That(cloth.TriangleCount, Is.EqualTo(64));
            Surface(cloth, out float area, out _);
            Assert.That(area, Is.EqualTo(2f).Within(1e-5f));
            ReadOnlySpan<int> t = cloth.Triangles;
            ReadOnlySpan<Vector3> x = cloth.Vertices;
            for (int k = 0; k < t.Length; k += 3)
                Assert.That(Vector3.Cross(x[t[k + 1]] - x[t[k]], x[t[k + 2]] - x[t[k]]).Y, Is.GreaterThan(0f), $"triangle {k / 3} faces +y");
        }

        [Test]
        public void Inverted_rest_tet_is_rejected_with_its_index()
        {
            var v = new[] { Vector3.Zero, Vector3.UnitX, Vector3.UnitY, Vector3.UnitZ, new Vector3(1, 1, 1) };
            var ex = Assert.Throws<ArgumentException>(() => SoftMesh.FromTetrahedra(v, new[] { 0, 1, 2, 3, 1, 2, 4, 3 }));
            Assert.That(ex!.Message, Does.Contain("tetrahedron 1").And.Contain("inverted"));
            Assert.That(ex.ParamName, Is.EqualTo("mesh.Tetrahedra"));
        }

        [Test]
        public void Degenerate_rest_tet_is_rejected_with_its_index()
        {
            var v = new[] { Vector3.Zero, Vector3.UnitX, Vector3.UnitY, Vector3.UnitZ, new Vector3(1, 1, 0) };
            var ex = Assert.Throws<ArgumentException>(() => SoftMesh.FromTetrahedra(v, new[] { 0, 1, 2, 3, 0, 1, 4, 2 }));
            Assert.That(ex!.Message, Does.Contain("tetrahedron 1").And.Contain("degenerate"));
        }

        [Test]
        public void NaN_vertex_is_rejected_with_its_index()
        {
            var v = new[] { Vector3.Zero, Vector3.UnitX, new Vector3(0, float.NaN, 0), Vector3.UnitZ };
            var ex = Assert.Throws<ArgumentException>(() => SoftMesh.FromTetrahedra(v, new[] { 0, 1, 2, 3 }));
            Assert.That(ex!.Message, Does.Contain("vertex 2"));
            Assert.That(ex.ParamName, Is.EqualTo("mesh.Vertices"));
        }

        [Test]
        public void Degenerate_triangle_and_unused_vertex_are_rejected()
        {
            var v = new[] { Vector3.Zero, Vector3.UnitX, new Vector3(2, 0, 0), Vector3.UnitZ };
            var ex = Assert.Throws<ArgumentException>(() => SoftMesh.FromTriangles(v, new[] { 0, 3, 1, 0, 1, 2 }));
            Assert.That(ex!.Message, Does.Contain("triangle 1").And.Contain("degenerate"));
            ex = Assert.Throws<ArgumentException>(() => SoftMesh.FromTriangles(v, new[] { 0, 3, 1 }));
            Assert.That(ex!.Message, Does.Contain("vertex 2"));
        }

        [Test]
        public void Bad_sizes_and_cell_counts_are_rejected()
        {
            Assert.That(Assert.Throws<ArgumentException>(() => SoftMesh.Box(new Vector3(1, 0, 1), 2, 2, 2))!.ParamName, Is.EqualTo("mesh.size"));
            Assert.That(Assert.Throws<ArgumentException>(() => SoftMesh.Box(Vector3.One, 2, 0, 2))!.ParamName, Is.EqualTo("mesh.cells[1]"));
            Assert.That(Assert.Throws<ArgumentException>(() => SoftMesh.Sphere(-1f, 4))!.ParamName, Is.EqualTo("mesh.radius"));
        }
    }
}
