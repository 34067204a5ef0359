using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;
using NUnit.Framework;

namespace Fulcrum.Tests.Collision
{
    /// <summary>
    /// Dedicated pair functions against the generic GJK/EPA path, and EPA against the
    /// separating axis test, over random poses.
    /// </summary>
    public class ConvexCrossCheckTests
    {
        const int Poses = 2000;
        const float Speculative = 0.05f;

        static ShapeGeometry RandomShape(Random r, ShapeType type)
        {
            float s() => 0.2f + 0.8f * (float)r.NextDouble();
            return type switch
            {
                ShapeType.Sphere => ShapeGeometry.Sphere(s()),
                ShapeType.Box => ShapeGeometry.Box(new Vector3(s(), s(), s())),
                _ => ShapeGeometry.Capsule(0.5f * s(), s()),
            };
        }

        static float MinSep(ContactBuffer b, out Vector3 normal)
        {
            float best = float.PositiveInfinity;
            normal = default;
            for (int p = 0; p < b.PatchCount; p++)
                for (int i = b.PatchStart[p]; i < b.PatchStart[p + 1]; i++)
                    if (b.Separation[i] < best) { best = b.Separation[i]; normal = b.PatchNormal[p]; }
            return best;
        }

        [TestCase(ShapeType.Sphere, ShapeType.Sphere, 1e-4f)]
        [TestCase(ShapeType.Sphere, ShapeType.Box, 1e-4f)]
        [TestCase(ShapeType.Sphere, ShapeType.Capsule, 1e-4f)]
        [TestCase(ShapeType.Capsule, ShapeType.Capsule, 1e-4f)]
        [TestCase(ShapeType.Capsule, ShapeType.Box, 1e-4f)]
        [TestCase(ShapeType.Box, ShapeType.Box, 0.02f)]
        public void Pair_function_agrees_with_the_convex_fallback_over_random_poses(ShapeType ta, ShapeType tb, float tolerance)
        {
            var r = new Random(1000 + 10 * (int)ta + (int)tb);
            var dedicated = new ContactBuffer();
            var fallback = new ContactBuffer();
            int compared = 0, deep = 0, failures = 0;
            string firstFailure = "";
            for (int n = 0; n < Poses; n++)
            {
                ShapeGeometry a = RandomShape(r, ta), b = RandomShape(r, tb);
                var pa = new Pose(CollisionTestKit.RandomVector(r, 0.3f), CollisionTestKit.RandomRotation(r));
                var pb = new Pose(CollisionTestKit.RandomVector(r, 1.5f), CollisionTestKit.RandomRotation(r));
                dedicated.Clear(Speculative);
                CollisionTable.Collide(a, pa, b, pb, dedicated);
                dedicated.Reduce();
                fallback.Clear(Speculative);
                ConvexCollider.Collide(SupportShape.From(a, pa), SupportShape.From(b, pb), fallback);
                fallback.Reduce();

                float sd = MinSep(dedicated, out Vector3 nd), sf = MinSep(fallback, out Vector3 nf);
                bool hasD = dedicated.PointCount > 0, hasF = fallback.PointCount > 0;
                string what = $"pose {n}: {a} at {pa.Position} {pa.Rotation} vs {b} at {pb.Position} {pb.Rotation}";
                if (hasD != hasF)
                {
                    // Only allowed right at the speculative boundary.
                    float s = hasD ? sd : sf;
                    if (s < Speculative - 2 * tolerance) { failures++; if (firstFailure == "") firstFailure = $"{what}: only one reports ({sd} vs {sf})"; }
                    continue;
                }
                if (!hasD) continue;
                compared++;
                // Separation of the deepest point: exact for rounded shapes; for boxes the face
                // preference of SAT and clipping may differ from EPA by the preference tolerance.
                // Deep overlaps (over 5 cm) may differ by 1 %: clipping to a reference face can
                // drop a deepest point that pokes out beside it.
                float allowed = tolerance * (1 + MathF.Abs(sf)) + (sf < -0.05f ? 0.01f * -sf : 0);
                if (MathF.Abs(sd - sf) > allowed)
                {
                    failures++;
                    if (firstFailure == "") firstFailure = $"{what}: separation {sd} vs {sf}";
                }
                else if (sf < -0.02f)
                {
                    deep++;
                    if (Vector3.Dot(nd, nf) < 0.9f && ta != ShapeType.Box)
                    {
                        failures++;
                        if (firstFailure == "") firstFailure = $"{what}: normals {nd} vs {nf}";
                    }
                }
            }
            Assert.That(compared, Is.GreaterThan(Poses / 5));
            Assert.That(deep, Is.GreaterThan(Poses / 10));
            Assert.That(failures, Is.EqualTo(0), firstFailure);
        }

        [Test]
        public void Epa_depth_equals_the_least_separating_axis_penetration_of_two_boxes()
        {
            var r = new Random(42);
            int penetrating = 0;
            for (int n = 0; n < Poses; n++)
            {
                Vector3 ha = new Vector3(0.2f) + CollisionTestKit.RandomVector(r, 0.1f) + new Vector3(0.4f);
                Vector3 hb = new Vector3(0.2f) + CollisionTestKit.RandomVector(r, 0.1f) + new Vector3(0.4f);
                var pa = new Pose(CollisionTestKit.RandomVector(r, 0.3f), CollisionTestKit.RandomRotation(r));
                var pb = new Pose(CollisionTestKit.RandomVector(r, 1.5f), CollisionTestKit.RandomRotation(r));
                var a = SupportShape.From(ShapeGeometry.Box(ha), pa);
                var b = SupportShape.From(ShapeGeometry.Box(hb), pb);
                float sat = SatSeparation(a, b, out Vector3 axis);
                float dist = Gjk.Distance(a, b, out _, out _, out Simplex simplex);
                if (sat > 1e-3f)
                {
                    // Separated: SAT is a lower bound of the distance, and both see the gap.
                    Assert.That(dist, Is.GreaterThanOrEqualTo(sat - 1e-4f), $"pose {n}");
                    continue;
                }
                if (sat > -1e-3f) continue;   // grazing: either answer is fine
                penetrating++;
                Assert.That(dist, Is.LessThan(1e-4f), $"pose {n}: GJK misses an overlap of {-sat}");
                Assert.That(Epa.Penetration(a, b, simplex, out Vector3 normal, out float depth, out Vector3 wa, out Vector3 wb), Is.True, $"pose {n}");
                Assert.That(depth, Is.EqualTo(-sat).Within(1e-4f * (1 + depth)), $"pose {n}");
                Assert.That(MathF.Abs(Vector3.Dot(normal, axis)), Is.GreaterThan(0.999f), $"pose {n}");
                // Witness points are depth apart along the normal.
                Assert.That(Vector3.Dot(wa - wb, normal), Is.EqualTo(depth).Within(1e-3f * (1 + depth)), $"pose {n}");
            }
            Assert.That(penetrating, Is.GreaterThan(Poses / 5));
        }

        [Test]
        public void Box_on_box_through_the_hull_path_gives_the_same_four_points_as_the_box_pair_function()
        {
            var corners = new Vector3[8];
            for (int i = 0; i < 8; i++) corners[i] = new Vector3((i & 1) != 0 ? 0.5f : -0.5f, (i & 2) != 0 ? 0.5f : -0.5f, (i & 4) != 0 ? 0.5f : -0.5f);
            var hull = ShapeGeometry.ConvexHull(corners);
            var box = ShapeGeometry.Box(new Vector3(0.5f));
            var pa = CollisionTestKit.At(0, 0, 0);
            var pb = CollisionTestKit.At(new Vector3(0.2f, 0.995f, 0.1f), CollisionTestKit.AboutY(10));
            var viaBox = CollisionTestKit.Collide(box, pa, box, pb);
            var viaHull = CollisionTestKit.Collide(hull, pa, hull, pb);
            Assert.That(viaHull.PointCount, Is.EqualTo(4));
            Assert.That(viaBox.PointCount, Is.EqualTo(4));
            Assert.That(Vector3.Distance(viaHull.PatchNormal[0], Vector3.UnitY), Is.LessThan(1e-5f));
            for (int i = 0; i < 4; i++)
            {
                Assert.That(viaHull.Separation[i], Is.EqualTo(-0.005f).Within(1e-5f));
                float nearest = float.MaxValue;
                for (int j = 0; j < 4; j++) nearest = MathF.Min(nearest, Vector3.Distance(viaHull.Position[i], viaBox.Position[j]));
                Assert.That(nearest, Is.LessThan(1e-5f));
            }
        }

        // Reference SAT over the 15 axes of two boxes: the largest separation and its axis.
        static float SatSeparation(in SupportShape a, in SupportShape b, out Vector3 bestAxis)
        {
            float best = float.MinValue;
            bestAxis = default;
            Span<Vector3> axes = stackalloc Vector3[15];
            int n = 0;
            Vector3[] ea = { a.Axes.C0, a.Axes.C1, a.Axes.C2 }, eb = { b.Axes.C0, b.Axes.C1, b.Axes.C2 };
            foreach (var e in ea) axes[n++] = e;
            foreach (var e in eb) axes[n++] = e;
            foreach (var x in ea) foreach (var y in eb) axes[n++] = Vector3.Cross(x, y);
            for (int i = 0; i < n; i++)
            {
                Vector3 l = axes[i];
                if (l.LengthSquared() < 1e-6f) continue;
                l = Vector3.Normalize(l);
                float maxA = Vector3.Dot(a.Support(l, out _), l), minA = Vector3.Dot(a.Support(-l, out _), l);
                float maxB = Vector3.Dot(b.Support(l, out _), l), minB = Vector3.Dot(b.Support(-l, out _), l);
                float s = MathF.Max(minB - maxA, minA - maxB);
                if (s > best) { best = s; bestAxis = l; }
            }
            return best;
        }
    }
}
