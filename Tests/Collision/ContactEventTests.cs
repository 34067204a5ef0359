using System.Collections.Generic;
using System.Numerics;
using Fulcrum.Collision;
using NUnit.Framework;

namespace Fulcrum.Tests.Collision
{
    public class ContactEventTests
    {
        const float Dt = 1 / 60f;

        static World NoGravity()
        {
            var s = WorldSettings.Default;
            s.Gravity = Vector3.Zero;
            s.EnableSleeping = false;
            return new World(s);
        }

        static (BodyHandle, ShapeHandle) Box(World w, Vector3 at, BodyType type = BodyType.Dynamic, bool sensor = false, float half = 0.5f)
        {
            BodyDef d = BodyDef.Default;
            d.Type = type;
            d.Position = at;
            BodyHandle b = w.CreateBody(d);
            ShapeDef sd = ShapeDef.Of(ShapeGeometry.Box(new Vector3(half)));
            sd.IsSensor = sensor;
            return (b, w.AddShape(b, sd));
        }

        static List<ContactEventKind> Kinds(World w)
        {
            var list = new List<ContactEventKind>();
            foreach (ContactEvent e in w.ContactEvents) list.Add(e.Kind);
            return list;
        }

        [Test]
        public void A_box_passing_through_another_reports_begin_then_persist_then_end()
        {
            var w = NoGravity();
            var (_, sa) = Box(w, Vector3.Zero, BodyType.Static);
            // Sliding off the top face without gravity (no normal force, so no friction): the
            // solver lets it go at 0.1 m per step. (Running into the side would stop it.)
            var (mover, sb) = Box(w, new Vector3(-0.95f, 1f, 0));
            w.GetBody(mover).LinearVelocity = new Vector3(6, 0, 0);
            var sequence = new List<ContactEventKind>();
            for (int i = 0; i < 40; i++)
            {
                w.Step(Dt);
                foreach (ContactEvent e in w.ContactEvents)
                {
                    Assert.That(e.ShapeA, Is.EqualTo(sa));
                    Assert.That(e.ShapeB, Is.EqualTo(sb));
                    Assert.That(e.IsSensor, Is.False);
                    if (e.Kind != ContactEventKind.End)
                    {
                        Assert.That(e.PointCount, Is.GreaterThan(0));
                        Assert.That(e.Normal.Length(), Is.EqualTo(1f).Within(1e-5f));
                        Assert.That(e.RelativeVelocity.X, Is.EqualTo(6f).Within(1e-4f));
                    }
                    sequence.Add(e.Kind);
                }
            }
            Assert.That(sequence[0], Is.EqualTo(ContactEventKind.Begin));
            Assert.That(sequence[sequence.Count - 1], Is.EqualTo(ContactEventKind.End));
            Assert.That(sequence.FindAll(k => k == ContactEventKind.Begin).Count, Is.EqualTo(1));
            Assert.That(sequence.FindAll(k => k == ContactEventKind.End).Count, Is.EqualTo(1));
            // Touching from x = -0.95 to x = +1.005 (slop): about 1.96 / 0.1 = 20 steps.
            Assert.That(sequence.Count, Is.InRange(19, 23));
        }

        [Test]
        public void Event_impulses_are_the_ones_the_solver_wrote_in_this_step()
        {
            var w = NoGravity();
            Box(w, new Vector3(0, -0.5f, 0), BodyType.Static);
            Box(w, new Vector3(0, 0.495f, 0));
            w.SoftBodyStage = new ImpulseWriter { NormalPerPoint = 2f };
            w.Step(Dt);
            Assert.That(w.ContactEvents.Length, Is.EqualTo(1));
            ContactEvent e = w.ContactEvents[0];
            Assert.That(e.Kind, Is.EqualTo(ContactEventKind.Begin));
            Assert.That(e.PointCount, Is.EqualTo(4));
            Assert.That(e.NormalImpulse, Is.EqualTo(2f * (1 + 2 + 3 + 4)).Within(1e-5f));
            Assert.That(e.Point.Y, Is.EqualTo(-0.0025f).Within(1e-5f));
            w.Step(Dt);
            Assert.That(w.ContactEvents[0].Kind, Is.EqualTo(ContactEventKind.Persist));
        }

        [Test]
        public void A_sensor_reports_overlap_begin_and_end_without_points()
        {
            var w = NoGravity();
            var (_, sensor) = Box(w, Vector3.Zero, BodyType.Static, sensor: true, half: 1f);
            var (ball, _) = Box(w, new Vector3(-2f, 0, 0), half: 0.25f);
            w.GetBody(ball).LinearVelocity = new Vector3(12, 0, 0);  // 0.2 m per step
            var kinds = new List<ContactEventKind>();
            for (int i = 0; i < 30; i++)
            {
                w.Step(Dt);
                foreach (ContactEvent e in w.ContactEvents)
                {
                    Assert.That(e.IsSensor, Is.True);
                    Assert.That(e.PointCount, Is.EqualTo(0));
                    Assert.That(e.ShapeA == sensor || e.ShapeB == sensor, Is.True);
                    kinds.Add(e.Kind);
                }
            }
            Assert.That(kinds[0], Is.EqualTo(ContactEventKind.Begin));
            Assert.That(kinds[kinds.Count - 1], Is.EqualTo(ContactEventKind.End));
            // Overlapping while the centre is within 1.25 of the sensor's: 2.5 / 0.2 = 12-13 steps.
            Assert.That(kinds.Count, Is.InRange(12, 15));
        }

        [Test]
        public void Removing_a_touching_shape_reports_end_first_in_the_next_step()
        {
            var w = NoGravity();
            Box(w, new Vector3(0, -0.5f, 0), BodyType.Static);
            var (_, top) = Box(w, new Vector3(0, 0.495f, 0));
            var (other, otherShape) = Box(w, new Vector3(3, 0.495f, 0));
            Box(w, new Vector3(3, -0.5f, 0), BodyType.Static);
            w.Step(Dt);
            Assert.That(Kinds(w), Is.EqualTo(new[] { ContactEventKind.Begin, ContactEventKind.Begin }));
            w.RemoveShape(top);
            w.DestroyBody(other);
            w.Step(Dt);
            var events = w.ContactEvents.ToArray();
            Assert.That(events.Length, Is.EqualTo(2));
            Assert.That(events[0].Kind, Is.EqualTo(ContactEventKind.End));
            Assert.That(events[0].ShapeB, Is.EqualTo(top));
            Assert.That(events[1].Kind, Is.EqualTo(ContactEventKind.End));
            Assert.That(events[1].ShapeA == otherShape || events[1].ShapeB == otherShape, Is.True);
            Assert.That(w.IsValid(events[0].ShapeB), Is.False);
            w.Step(Dt);
            Assert.That(w.ContactEvents.Length, Is.EqualTo(0));
        }

        [Test]
        public void Events_come_in_shape_pair_order()
        {
            var w = NoGravity();
            Box(w, new Vector3(0, -0.5f, 0), BodyType.Static, half: 10f);
            for (int i = 0; i < 10; i++) Box(w, new Vector3(-9 + 2 * ((i * 7) % 10), 9.995f, 0));
            w.Step(Dt);
            var events = w.ContactEvents.ToArray();
            Assert.That(events.Length, Is.EqualTo(10));
            for (int i = 1; i < events.Length; i++)
                Assert.That(PairMap.Key(events[i - 1].ShapeA.Index, events[i - 1].ShapeB.Index),
                    Is.LessThan(PairMap.Key(events[i].ShapeA.Index, events[i].ShapeB.Index)));
        }

        [Test]
        public void Sleeping_pairs_report_nothing()
        {
            var w = NoGravity();
            for (int i = 0; i < 2; i++)
            {
                BodyDef d = BodyDef.Dynamic(new Vector3(0, 0.99f * i, 0));
                d.IsAwake = false;
                w.AddShape(w.CreateBody(d), ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            }
            w.Step(Dt);
            Assert.That(w.ContactEvents.Length, Is.EqualTo(0));
        }
    }
}
