using System;
using System.Collections.Generic;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Tests.Foundation;
using NUnit.Framework;

namespace Fulcrum.Tests.Collision
{
    public class ParallelNarrowPhaseTests
    {
        const float Dt = 1 / 60f;

        // A mesh floor (a grid of triangles), static walls, and a pile of boxes, spheres,
        // capsules and two hulls dropped in layers so they land, tumble and collide.
        static World MixedPile(int threads)
        {
            var s = WorldSettings.Default;
            s.Threads = threads;
            var w = new World(s);
            w.AddShape(w.CreateBody(BodyDef.Static(Vector3.Zero)), ShapeDef.Of(ShapeGeometry.TriangleMesh(Floor(8, 8))));
            var hull = ConvexHull.Create(new[]
            {
                new Vector3(-0.4f, -0.4f, -0.4f), new Vector3(0.4f, -0.4f, -0.4f), new Vector3(0, -0.4f, 0.4f),
                new Vector3(-0.25f, 0.4f, 0), new Vector3(0.25f, 0.4f, 0.1f), new Vector3(0, 0.4f, -0.3f),
            });
            var r = new Random(7);
            int made = 0;
            for (int y = 0; y < 4; y++)
                for (int x = 0; x < 6; x++)
                    for (int z = 0; z < 6; z++, made++)
                    {
                        BodyDef d = BodyDef.Dynamic(new Vector3(-3 + x * 1.1f + 0.3f * (y % 2), 0.6f + 1.05f * y, -3 + z * 1.1f));
                        d.AngularVelocity = new Vector3((float)r.NextDouble() - 0.5f, (float)r.NextDouble() - 0.5f, (float)r.NextDouble() - 0.5f);
                        BodyHandle b = w.CreateBody(d);
                        ShapeGeometry g = made == 40 || made == 100 ? ShapeGeometry.ConvexHull(hull) : (made % 3) switch
                        {
                            0 => ShapeGeometry.Box(new Vector3(0.45f, 0.4f, 0.35f)),
                            1 => ShapeGeometry.Sphere(0.45f),
                            _ => ShapeGeometry.Capsule(0.3f, 0.2f),
                        };
                        w.AddShape(b, ShapeDef.Of(g));
                    }
            return w;
        }

        // A square grid of cells x cells quads, 2 * half metres wide, at y = 0.
        static TriangleMesh Floor(float half, int cells)
        {
            var v = new List<Vector3>();
            var t = new List<int>();
            for (int z = 0; z <= cells; z++)
                for (int x = 0; x <= cells; x++)
                    v.Add(new Vector3(-half + 2 * half * x / cells, 0, -half + 2 * half * z / cells));
            for (int z = 0; z < cells; z++)
                for (int x = 0; x < cells; x++)
                {
                    int i = z * (cells + 1) + x;
                    t.AddRange(new[] { i, i + cells + 1, i + 1, i + 1, i + cells + 1, i + cells + 2 });
                }
            return TriangleMesh.Create(v.ToArray(), t.ToArray());
        }

        static int Bits(float f) => BitConverter.SingleToInt32Bits(f);

        [Test]
        public void A_mixed_pile_on_four_threads_matches_one_thread_bit_for_bit()
        {
            World one = MixedPile(1), four = MixedPile(4);
            int events = 0;
            for (int step = 0; step < 240; step++)
            {
                one.Step(Dt);
                four.Step(Dt);
                ReadOnlySpan<ContactEvent> a = one.ContactEvents, b = four.ContactEvents;
                Assert.That(b.Length, Is.EqualTo(a.Length), $"event count at step {step}");
                for (int i = 0; i < a.Length; i++)
                {
                    Assert.That(b[i].Kind, Is.EqualTo(a[i].Kind), $"event {i} kind at step {step}");
                    Assert.That(b[i].ShapeA, Is.EqualTo(a[i].ShapeA), $"event {i} shape A at step {step}");
                    Assert.That(b[i].ShapeB, Is.EqualTo(a[i].ShapeB), $"event {i} shape B at step {step}");
                    Assert.That(b[i].PointCount, Is.EqualTo(a[i].PointCount), $"event {i} points at step {step}");
                    Assert.That(Bits(b[i].Normal.X) == Bits(a[i].Normal.X) && Bits(b[i].Normal.Y) == Bits(a[i].Normal.Y) && Bits(b[i].Normal.Z) == Bits(a[i].Normal.Z), Is.True, $"event {i} normal at step {step}");
                    Assert.That(Bits(b[i].NormalImpulse), Is.EqualTo(Bits(a[i].NormalImpulse)), $"event {i} impulse at step {step}");
                }
                events += a.Length;
            }
            Assert.That(events, Is.GreaterThan(1000), "the pile made contacts");
            Assert.That(four.ParallelNarrowPhaseSteps, Is.GreaterThan(200), "steps whose pair functions ran on the pool");
            Assert.That(one.ParallelNarrowPhaseSteps, Is.EqualTo(0));
            Assert.That(four.ParallelManifoldRewrites, Is.GreaterThan(1000), "contacts whose manifolds the pool rewrote in place");
            Assert.That(four.ParallelPairSearch.Runs, Is.GreaterThan(0), "steps whose pair search ran on the pool");
            Assert.That(four.ParallelPairSearch.Overflows, Is.GreaterThan(0), "pair-search blocks that filled and were finished on the stepping thread");

            BodyStorage sa = one.Bodies, sb = four.Bodies;
            Assert.That(sb.ActiveCount, Is.EqualTo(sa.ActiveCount));
            int moved = 0;
            for (int k = 0; k < sa.ActiveCount; k++)
            {
                int i = sa.Active[k];
                Assert.That(sb.Active[k], Is.EqualTo(i));
                Vector3 pa = sa.Position[i], pb = sb.Position[i];
                Quaternion qa = sa.Rotation[i], qb = sb.Rotation[i];
                Assert.That(new[] { Bits(pb.X), Bits(pb.Y), Bits(pb.Z) }, Is.EqualTo(new[] { Bits(pa.X), Bits(pa.Y), Bits(pa.Z) }), $"position of body slot {i}");
                Assert.That(new[] { Bits(qb.X), Bits(qb.Y), Bits(qb.Z), Bits(qb.W) }, Is.EqualTo(new[] { Bits(qa.X), Bits(qa.Y), Bits(qa.Z), Bits(qa.W) }), $"rotation of body slot {i}");
                if (sa.Type[i] == BodyType.Dynamic && pa.Y < 0.6f) moved++;
            }
            Assert.That(moved, Is.GreaterThan(36), "bodies that fell onto the floor or pile");
        }

        [Test]
        public void A_warm_mixed_pile_on_four_threads_allocates_nothing_per_step()
        {
            World w = MixedPile(4);
            AllocationTests.AllocatedOverSteps(w, 300, Dt);
            long before = w.ParallelNarrowPhaseSteps;
            Assert.That(AllocationTests.AllocatedOverSteps(w, 300, Dt), Is.EqualTo(0), "bytes allocated over 300 warm steps");
            Assert.That(w.ParallelNarrowPhaseSteps - before, Is.GreaterThan(0), "steps whose pair functions ran on the pool");
        }
    }
}
