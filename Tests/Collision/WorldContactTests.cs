using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;
using NUnit.Framework;

namespace Fulcrum.Tests.Collision
{
    public class WorldContactTests
    {
        static World NoGravity()
        {
            var s = WorldSettings.Default;
            s.Gravity = Vector3.Zero;
            s.EnableSleeping = false;
            return new World(s);
        }

        static BodyHandle Box(World w, Vector3 at, Vector3 half, BodyType type = BodyType.Dynamic, int layer = 0, uint mask = uint.MaxValue, bool sensor = false)
        {
            BodyDef d = BodyDef.Default;
            d.Type = type;
            d.Position = at;
            BodyHandle b = w.CreateBody(d);
            ShapeDef sd = ShapeDef.Of(ShapeGeometry.Box(half));
            sd.Layer = layer;
            sd.CollidesWith = mask;
            sd.IsSensor = sensor;
            w.AddShape(b, sd);
            return b;
        }

        [Test]
        public void Box_resting_on_a_static_box_gives_one_manifold_of_four_points_with_anchors_from_the_centres()
        {
            var w = NoGravity();
            BodyHandle ground = Box(w, new Vector3(0, -0.5f, 0), new Vector3(5, 0.5f, 5), BodyType.Static);
            BodyHandle box = Box(w, new Vector3(1, 0.495f, 0), new Vector3(0.5f));
            w.Step(1 / 60f);
            Assert.That(w.Contacts.ManifoldCount, Is.EqualTo(1));
            ContactManifold m = w.Contacts[0];
            Assert.That(m.PointCount, Is.EqualTo(4));
            Assert.That(m.BodyA, Is.EqualTo(ground.Index));
            Assert.That(m.BodyB, Is.EqualTo(box.Index));
            Assert.That(Vector3.Distance(m.Normal, Vector3.UnitY), Is.LessThan(1e-6f));
            Assert.That(m.Friction, Is.EqualTo(0.6f).Within(1e-6f));
            for (int i = 0; i < 4; i++)
            {
                ContactPoint p = ContactManifold.Point(ref m, i);
                Assert.That(p.Separation, Is.EqualTo(-0.005f).Within(1e-5f));
                Assert.That(Vector3.Distance(p.AnchorB, p.Position - new Vector3(1, 0.495f, 0)), Is.LessThan(1e-5f));
                Assert.That(Vector3.Distance(p.AnchorA, p.Position - new Vector3(0, -0.5f, 0)), Is.LessThan(1e-5f));
                Assert.That(p.Persisted, Is.False);
            }
            Assert.That(w.MaxPenetration, Is.EqualTo(0.005f).Within(1e-5f));
            Assert.That(w.ContactCount, Is.EqualTo(4));
        }

        [Test]
        public void Resting_box_keeps_its_feature_ids_and_receives_last_steps_impulses_back()
        {
            var w = NoGravity();
            Box(w, new Vector3(0, -0.5f, 0), new Vector3(5, 0.5f, 5), BodyType.Static);
            Box(w, new Vector3(0, 0.495f, 0), new Vector3(0.5f));
            w.SoftBodyStage = new ImpulseWriter();
            w.Step(1 / 60f);
            // What the "solver" wrote for each feature id in the first step.
            var expected = new System.Collections.Generic.Dictionary<uint, (float, float, float)>();
            ContactManifold first = w.Contacts[0];
            for (int i = 0; i < 4; i++)
            {
                ContactPoint p = ContactManifold.Point(ref first, i);
                Assert.That(p.Persisted, Is.False);
                expected[p.FeatureId] = (1f + i, 0.1f * i, -0.2f * i);
            }
            // The written impulses went back to the persistent manifold...
            ContactManifold pooled = w.ContactGraph.Manifolds[w.Contacts.Source[0]];
            for (int i = 0; i < 4; i++)
            {
                ContactPoint p = ContactManifold.Point(ref pooled, i);
                var (n, t1, t2) = expected[p.FeatureId];
                Assert.That(p.NormalImpulse, Is.EqualTo(n));
                Assert.That(p.TangentImpulse1, Is.EqualTo(t1));
                Assert.That(p.TangentImpulse2, Is.EqualTo(t2));
            }
            // ...and next step's points with the same feature ids took them over (the solver then
            // overwrites them with its own, so only the carry flag is left to see).
            w.SoftBodyStage = null;
            w.Step(1 / 60f);
            Assert.That(w.Contacts.ManifoldCount, Is.EqualTo(1));
            ContactManifold m = w.Contacts[0];
            Assert.That(m.PointCount, Is.EqualTo(4));
            for (int i = 0; i < 4; i++)
            {
                ContactPoint p = ContactManifold.Point(ref m, i);
                Assert.That(expected.ContainsKey(p.FeatureId), Is.True, "feature id changed");
                Assert.That(p.Persisted, Is.True);
            }
            // The ids stay for many steps.
            for (int step = 0; step < 30; step++)
            {
                w.Step(1 / 60f);
                m = w.Contacts[0];
                for (int i = 0; i < 4; i++)
                    Assert.That(expected.ContainsKey(ContactManifold.Point(ref m, i).FeatureId), Is.True);
            }
        }

        [Test]
        public void Shapes_on_the_same_body_never_collide()
        {
            var w = NoGravity();
            BodyHandle b = w.CreateBody(BodyDef.Dynamic(Vector3.Zero));
            w.AddShape(b, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            w.AddShape(b, ShapeDef.Of(ShapeGeometry.Sphere(0.6f)));
            w.Step(1 / 60f);
            Assert.That(w.ContactGraph.Count, Is.EqualTo(0));
        }

        [Test]
        public void Static_and_kinematic_bodies_do_not_collide_with_each_other()
        {
            var w = NoGravity();
            Box(w, Vector3.Zero, new Vector3(1), BodyType.Static);
            Box(w, new Vector3(0.5f, 0, 0), new Vector3(1), BodyType.Static);
            Box(w, new Vector3(0, 0.5f, 0), new Vector3(1), BodyType.Kinematic);
            Box(w, new Vector3(0, 0, 0.5f), new Vector3(1), BodyType.Kinematic);
            w.Step(1 / 60f);
            Assert.That(w.ContactGraph.Count, Is.EqualTo(0));
            Assert.That(w.Contacts.ManifoldCount, Is.EqualTo(0));
        }

        [Test]
        public void Kinematic_against_dynamic_makes_a_manifold()
        {
            var w = NoGravity();
            Box(w, Vector3.Zero, new Vector3(0.5f), BodyType.Kinematic);
            Box(w, new Vector3(0, 0.99f, 0), new Vector3(0.5f));
            w.Step(1 / 60f);
            Assert.That(w.Contacts.ManifoldCount, Is.EqualTo(1));
        }

        [Test]
        public void Layer_masks_must_accept_each_other_for_a_pair_to_collide()
        {
            var w = NoGravity();
            Box(w, Vector3.Zero, new Vector3(0.5f), BodyType.Static, layer: 1, mask: ~(1u << 2));
            Box(w, new Vector3(0, 0.99f, 0), new Vector3(0.5f), layer: 2);                  // rejected by the ground's mask
            Box(w, new Vector3(3, 0, 0), new Vector3(0.5f), BodyType.Static, layer: 1);
            Box(w, new Vector3(3, 0.99f, 0), new Vector3(0.5f), layer: 3, mask: 1u << 1);   // accepts layer 1, accepted by it
            Box(w, new Vector3(6, 0, 0), new Vector3(0.5f), BodyType.Static, layer: 1);
            Box(w, new Vector3(6, 0.99f, 0), new Vector3(0.5f), layer: 3, mask: 1u << 4);   // does not accept layer 1
            w.Step(1 / 60f);
            Assert.That(w.Contacts.ManifoldCount, Is.EqualTo(1));
            Assert.That(w.Contacts[0].BodyB, Is.EqualTo(3));
        }

        [Test]
        public void Sensor_overlap_makes_no_manifold_for_the_solver()
        {
            var w = NoGravity();
            Box(w, Vector3.Zero, new Vector3(1), BodyType.Static, sensor: true);
            Box(w, new Vector3(0, 0.5f, 0), new Vector3(0.5f));
            w.Step(1 / 60f);
            Assert.That(w.ContactGraph.Count, Is.EqualTo(1));
            Assert.That(w.Contacts.ManifoldCount, Is.EqualTo(0));
        }

        [Test]
        public void An_awake_body_touching_a_sleeping_one_wakes_it()
        {
            var w = NoGravity();
            BodyDef sleeping = BodyDef.Dynamic(new Vector3(0, 0.99f, 0));
            sleeping.IsAwake = false;
            BodyHandle sleeper = w.CreateBody(sleeping);
            w.AddShape(sleeper, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            BodyDef far = BodyDef.Dynamic(new Vector3(5, 0, 0));
            far.IsAwake = false;
            BodyHandle untouched = w.CreateBody(far);
            w.AddShape(untouched, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            Box(w, Vector3.Zero, new Vector3(0.5f));
            Assert.That(w.GetBody(sleeper).IsAwake, Is.False);
            w.Step(1 / 60f);
            Assert.That(w.GetBody(sleeper).IsAwake, Is.True);
            Assert.That(w.GetBody(untouched).IsAwake, Is.False);
            Assert.That(w.Contacts.ManifoldCount, Is.EqualTo(1));
        }

        [Test]
        public void Two_sleeping_bodies_touching_are_not_updated_and_send_nothing_to_the_solver()
        {
            var w = NoGravity();
            for (int i = 0; i < 2; i++)
            {
                BodyDef d = BodyDef.Dynamic(new Vector3(0, 0.99f * i, 0));
                d.IsAwake = false;
                w.AddShape(w.CreateBody(d), ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            }
            w.Step(1 / 60f);
            Assert.That(w.Contacts.ManifoldCount, Is.EqualTo(0));
        }

        [Test]
        public void Bodies_flying_apart_lose_their_contact_once_the_fat_boxes_part()
        {
            var w = NoGravity();
            Box(w, Vector3.Zero, new Vector3(0.5f));
            BodyHandle b = Box(w, new Vector3(0, 0.99f, 0), new Vector3(0.5f));
            w.Step(1 / 60f);
            Assert.That(w.ContactGraph.Count, Is.EqualTo(1));
            w.GetBody(b).LinearVelocity = new Vector3(0, 6, 0);
            for (int i = 0; i < 10; i++) w.Step(1 / 60f);
            Assert.That(w.ContactGraph.Count, Is.EqualTo(0));
            Assert.That(w.Contacts.ManifoldCount, Is.EqualTo(0));
        }

        [Test]
        public void Fast_body_gets_a_speculative_point_before_it_reaches_the_floor()
        {
            var w = NoGravity();
            Box(w, new Vector3(0, -0.5f, 0), new Vector3(5, 0.5f, 5), BodyType.Static);
            BodyHandle b = Box(w, new Vector3(0, 0.8f, 0), new Vector3(0.5f));
            w.GetBody(b).LinearVelocity = new Vector3(0, -30, 0);   // 0.5 m per step: gap 0.3 m
            w.Step(1 / 60f);
            Assert.That(w.Contacts.ManifoldCount, Is.EqualTo(1));
            ContactPoint p = w.Contacts[0].Point0;
            Assert.That(p.Separation, Is.EqualTo(0.3f).Within(1e-4f));
        }

        [Test]
        public void Manifolds_are_ordered_by_shape_pair()
        {
            var w = NoGravity();
            var rng = new Random(3);
            for (int i = 0; i < 60; i++)
                Box(w, CollisionTestKit.RandomVector(rng, 2f), new Vector3(0.4f));
            w.Step(1 / 60f);
            Assert.That(w.Contacts.ManifoldCount, Is.GreaterThan(20));
            for (int k = 1; k < w.Contacts.ManifoldCount; k++)
            {
                ContactManifold a = w.Contacts[k - 1], b = w.Contacts[k];
                Assert.That(PairMap.Key(a.ShapeA, a.ShapeB), Is.LessThan(PairMap.Key(b.ShapeA, b.ShapeB)));
            }
        }

        [Test]
        public void Every_pair_of_overlapping_shapes_has_a_contact_after_a_step()
        {
            var w = NoGravity();
            var rng = new Random(11);
            var bodies = new BodyHandle[200];
            for (int i = 0; i < bodies.Length; i++)
            {
                bodies[i] = Box(w, CollisionTestKit.RandomVector(rng, 6f), new Vector3(0.3f + (float)rng.NextDouble() * 0.4f));
                w.GetBody(bodies[i]).LinearVelocity = CollisionTestKit.RandomVector(rng, 3f);
            }
            for (int step = 0; step < 20; step++)
            {
                w.Step(1 / 60f);
                for (int i = 0; i < bodies.Length; i++)
                    for (int j = i + 1; j < bodies.Length; j++)
                    {
                        Aabb a = w.Shapes.WorldAabb[i], b = w.Shapes.WorldAabb[j];
                        if (a.Overlaps(b))
                            Assert.That(w.ContactGraph.Find(i, j), Is.GreaterThanOrEqualTo(0), $"step {step}: {i}-{j} missing");
                    }
            }
        }

        [Test]
        public void A_pile_of_resting_boxes_steps_without_allocating()
        {
            var w = NoGravity();
            Box(w, new Vector3(0, -0.5f, 0), new Vector3(20, 0.5f, 20), BodyType.Static);
            for (int x = 0; x < 10; x++)
                for (int y = 0; y < 5; y++)
                    for (int z = 0; z < 4; z++)
                        Box(w, new Vector3(x * 1.0f, 0.495f + y * 0.99f, z * 1.0f), new Vector3(0.5f));
            for (int i = 0; i < 5; i++) w.Step(1 / 60f);
            // Summed per step, so that nothing but Step is inside the measurement.
            long allocated = 0;
            for (int i = 0; i < 30; i++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                w.Step(1 / 60f);
                long a = GC.GetAllocatedBytesForCurrentThread() - before;
                if (a != 0) TestContext.Out.WriteLine($"ALLOCDIAG step {i}: {a} B, manifolds {w.Contacts.ManifoldCount}, reused {w.ReusedManifoldPairCount}");
                allocated += a;
            }
            Assert.That(allocated, Is.EqualTo(0));
            Assert.That(w.Contacts.ManifoldCount, Is.GreaterThan(300));
        }
    

        [Test]
        public void A_mixed_scene_with_mesh_hulls_sensors_ccd_and_events_steps_without_allocating()
        {
            var w = NoGravity();
            var mesh = TriangleMesh.Create(
                new[] { new Vector3(-10, 0, -10), new Vector3(10, 0, -10), new Vector3(10, 0, 10), new Vector3(-10, 0, 10) },
                new[] { 0, 3, 2, 0, 2, 1 });
            w.AddShape(w.CreateBody(BodyDef.Static(Vector3.Zero)), ShapeDef.Of(ShapeGeometry.TriangleMesh(mesh)));
            ShapeDef sensor = ShapeDef.Of(ShapeGeometry.Box(new Vector3(3, 1, 3)));
            sensor.IsSensor = true;
            w.AddShape(w.CreateBody(BodyDef.Static(new Vector3(0, 1, 0))), sensor);
            var hull = ConvexHull.Create(new[] { new Vector3(-0.3f, 0, -0.3f), new Vector3(0.3f, 0, -0.3f), new Vector3(0, 0, 0.4f), new Vector3(0, 0.5f, 0) });
            var r = new Random(4);
            for (int i = 0; i < 40; i++)
            {
                BodyDef d = BodyDef.Dynamic(new Vector3(-6 + (i % 8) * 1.5f, 0.499f, -4 + (i / 8) * 1.5f));
                d.LinearVelocity = CollisionTestKit.RandomVector(r, 0.3f) * new Vector3(1, 0, 1);
                d.Ccd = i % 10 == 0;
                BodyHandle b = w.CreateBody(d);
                ShapeGeometry g = (i % 4) switch
                {
                    0 => ShapeGeometry.Box(new Vector3(0.5f)),
                    1 => ShapeGeometry.ConvexHull(hull),
                    2 => ShapeGeometry.Capsule(0.2f, 0.3f),
                    _ => ShapeGeometry.Sphere(0.5f),
                };
                w.AddShape(b, ShapeDef.Of(g));
            }
            for (int i = 0; i < 20; i++) w.Step(1 / 60f);
            long allocated = 0;
            for (int i = 0; i < 30; i++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                w.Step(1 / 60f);
                allocated += GC.GetAllocatedBytesForCurrentThread() - before;
            }
            Assert.That(allocated, Is.EqualTo(0));
            Assert.That(w.ContactEvents.Length, Is.GreaterThan(10));
        }
    }
}
