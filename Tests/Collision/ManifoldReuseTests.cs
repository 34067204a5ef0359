using System;
using System.Numerics;
using Fulcrum.Collision;
using NUnit.Framework;

namespace Fulcrum.Tests.Collision
{
    /// <summary>
    /// Manifold reuse (WorldSettings.ManifoldReuseDistance / ManifoldReuseAngle): a pair that
    /// barely moved relative to itself keeps its manifold, its points carried with the shapes.
    /// The carried points are checked against the pair function's own answer.
    /// </summary>
    public class ManifoldReuseTests
    {
        static World MakeWorld(float reuseDistance, bool gravity = true)
        {
            var s = WorldSettings.Default;
            s.EnableSleeping = false;
            s.ManifoldReuseDistance = reuseDistance;
            if (!gravity) s.Gravity = Vector3.Zero;
            return new World(s);
        }

        static BodyHandle Box(World w, Vector3 at, Vector3 half, BodyType type = BodyType.Dynamic, Quaternion? rotation = null)
        {
            BodyDef d = BodyDef.Default;
            d.Type = type;
            d.Position = at;
            d.Rotation = rotation ?? Quaternion.Identity;
            BodyHandle b = w.CreateBody(d);
            w.AddShape(b, ShapeDef.Of(ShapeGeometry.Box(half)));
            return b;
        }

        // A small pile: a tilted box on a box on the ground, settled for a second.
        static (World world, BodyHandle top) Pile(float reuseDistance)
        {
            World w = MakeWorld(reuseDistance);
            Box(w, new Vector3(0, -0.5f, 0), new Vector3(5, 0.5f, 5), BodyType.Static);
            Box(w, new Vector3(0, 0.5f, 0), new Vector3(0.5f));
            BodyHandle top = Box(w, new Vector3(0.2f, 1.4f, 0.1f), new Vector3(0.4f, 0.3f, 0.35f), rotation: Quaternion.CreateFromAxisAngle(Vector3.UnitY, 0.4f));
            for (int n = 0; n < 60; n++) w.Step(1 / 60f);
            return (w, top);
        }

        [Test]
        public void Resting_pairs_are_reused_and_their_points_match_the_pair_function_to_a_micrometre()
        {
            (World w, _) = Pile(0.001f);
            w.Step(1 / 60f);
            Assert.That(w.ReusedManifoldPairCount, Is.EqualTo(2), "both resting pairs carried over");

            // What the pair function says for the same poses, point by point (same feature ids).
            var buffer = new ContactBuffer();
            int compared = 0;
            for (int k = 0; k < w.Contacts.ManifoldCount; k++)
            {
                ref ContactManifold m = ref w.Contacts[k];
                buffer.Clear(1f);
                CollisionTable.Collide(w.Shapes.Geometry[m.ShapeA], w.ShapeWorldPose(m.ShapeA), w.Shapes.Geometry[m.ShapeB], w.ShapeWorldPose(m.ShapeB), buffer);
                buffer.Reduce();
                Assert.That(Vector3.Distance(buffer.PatchNormal[0], m.Normal), Is.LessThan(1e-5f));
                for (int i = 0; i < m.PointCount; i++)
                {
                    ContactPoint p = ContactManifold.Point(ref m, i);
                    int j = Array.IndexOf(buffer.Id, p.FeatureId, 0, buffer.PointCount);
                    Assert.That(j, Is.GreaterThanOrEqualTo(0), "the carried point still exists");
                    Assert.That(p.Separation, Is.EqualTo(buffer.Separation[j]).Within(1e-6f));
                    Assert.That(Vector3.Distance(p.Position, buffer.Position[j]), Is.LessThan(1e-3f), "within the reuse distance");
                    Assert.That(p.Persisted, Is.True);
                    compared++;
                }
            }
            Assert.That(compared, Is.GreaterThanOrEqualTo(8));
        }

        [Test]
        public void Reuse_changes_a_settled_pile_by_less_than_a_tenth_of_a_millimetre()
        {
            (World on, BodyHandle topOn) = Pile(0.001f);
            (World off, BodyHandle topOff) = Pile(0f);
            for (int n = 0; n < 120; n++)
            {
                on.Step(1 / 60f);
                off.Step(1 / 60f);
            }
            Assert.That(off.ReusedManifoldPairCount, Is.EqualTo(0));
            float d = Vector3.Distance(on.GetBody(topOn).Position, off.GetBody(topOff).Position);
            Assert.That(d, Is.LessThan(1e-4f));
        }

        [Test]
        public void A_teleported_body_gets_its_manifold_computed_again()
        {
            (World w, BodyHandle top) = Pile(0.001f);
            w.Step(1 / 60f);
            Assert.That(w.ReusedManifoldPairCount, Is.EqualTo(2));
            var b = w.GetBody(top);
            b.Position += new Vector3(0.05f, 0, 0);
            w.Step(1 / 60f);
            Assert.That(w.ReusedManifoldPairCount, Is.EqualTo(1), "only the untouched pair carried over");
        }

        [Test]
        public void A_resting_box_set_spinning_sees_its_far_edge_coming_before_it_goes_through()
        {
            // A cube touching the ground along one edge, tilted 3 degrees: its far edge is 5 cm
            // up, beyond the resting speculative margin (2 cm), so the stored manifold has only
            // the near edge. Spun at 20 rad/s, the far edge comes down 30 cm in one step: the
            // grown speculative distance must force the pair function to run again.
            World w = MakeWorld(0.001f, gravity: false);
            Box(w, new Vector3(0, -0.5f, 0), new Vector3(5, 0.5f, 5), BodyType.Static);
            float tilt = 3f * MathF.PI / 180f;
            Quaternion q = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, tilt);
            // Lowest corner edge (x = -0.5, y = -0.5 in the body) on the ground.
            Vector3 corner = Vector3.Transform(new Vector3(-0.5f, -0.5f, 0), q);
            BodyHandle box = Box(w, -corner + new Vector3(0, -0.001f, 0), new Vector3(0.5f), rotation: q);
            for (int n = 0; n < 5; n++) w.Step(1 / 60f);
            Assert.That(w.ReusedManifoldPairCount, Is.EqualTo(1), "the resting pair is carried over");
            var b = w.GetBody(box);
            b.AngularVelocity = new Vector3(0, 0, -20);
            w.Step(1 / 60f);
            w.Step(1 / 60f);
            Assert.That(w.MaxPenetration, Is.LessThan(0.02f));
        }

        [TestCase(0.1f, 1)]
        [TestCase(2f, 0)]
        public void A_small_turn_is_reused_only_while_the_shapes_far_points_stay_within_half_the_margin(float halfLength, int reused)
        {
            // A bar lying on the ground, turned 1 degree about its centre (within the 2 degree
            // limit): a 0.2 m bar's ends move 3.5 mm (reused), a 4 m bar's 35 mm (computed again).
            World w = MakeWorld(0.001f, gravity: false);
            Box(w, new Vector3(0, -0.5f, 0), new Vector3(10, 0.5f, 10), BodyType.Static);
            BodyHandle bar = Box(w, new Vector3(0, 0.049f, 0), new Vector3(halfLength, 0.05f, 0.05f));
            for (int n = 0; n < 3; n++) w.Step(1 / 60f);
            Assert.That(w.ReusedManifoldPairCount, Is.EqualTo(1));
            var b = w.GetBody(bar);
            b.Rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitY, MathF.PI / 180f) * b.Rotation;
            b.LinearVelocity = Vector3.Zero;
            b.AngularVelocity = Vector3.Zero;
            w.Step(1 / 60f);
            Assert.That(w.ReusedManifoldPairCount, Is.EqualTo(reused));
        }

        [Test]
        public void Reuse_settings_are_checked()
        {
            var s = WorldSettings.Default;
            s.ManifoldReuseDistance = -1;
            Assert.That(() => new World(s), Throws.ArgumentException.With.Message.Contains("ManifoldReuseDistance"));
            s = WorldSettings.Default;
            s.ManifoldReuseAngle = float.NaN;
            Assert.That(() => new World(s), Throws.ArgumentException.With.Message.Contains("ManifoldReuseAngle"));
        }
    }
}
