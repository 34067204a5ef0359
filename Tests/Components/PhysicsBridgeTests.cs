using System;
using System.Collections.Generic;
using System.Numerics;
using System.Threading;
using Fulcrum.Collision;
using Fulcrum.Components;
using NUnit.Framework;

namespace Fulcrum.Tests.Components
{
    public class PhysicsBridgeTests
    {
        /// <summary>A custom engine's object: a plain position and rotation.</summary>
        public sealed class Thing : IPhysicsEntity
        {
            public string Name;
            public Vector3 Position;
            public Quaternion Rotation = Quaternion.Identity;
            public Thing(string name, Vector3 at) { Name = name; Position = at; }
            public void GetPose(out Vector3 position, out Quaternion rotation) { position = Position; rotation = Rotation; }
            public void SetPose(Vector3 position, Quaternion rotation) { Position = position; Rotation = rotation; }
            public override string ToString() => Name;
        }

        static PhysicsBridge NewBridge(float fixedDt = 0.25f, bool interpolate = true, int haptics = 1024)
        {
            WorldSettings ws = WorldSettings.Default;
            ws.Gravity = Vector3.Zero;
            PhysicsBridgeSettings s = PhysicsBridgeSettings.Default;
            s.FixedDt = fixedDt;
            s.Interpolate = interpolate;
            s.HapticsCapacity = haptics;
            return new PhysicsBridge(new World(ws), s);
        }

        static readonly ShapeDef Ball = ShapeDef.Of(ShapeGeometry.Sphere(0.5f));

        [Test]
        public void Physics_driven_entity_gets_interpolated_poses_one_step_behind()
        {
            using PhysicsBridge bridge = NewBridge();
            var thing = new Thing("ball", Vector3.Zero);
            ProxyHandle p = bridge.Register(thing, BodyDef.Default, Ball);
            bridge.SetLinearVelocity(p, new Vector3(1, 0, 0));

            void Frame(float dt) { bridge.SyncFromGame(); bridge.Step(dt); bridge.SyncToGame(); }
            Frame(0.25f);
            Assert.That(thing.Position.X, Is.EqualTo(0f).Within(1e-6f), "alpha 0 right after a step: the previous pose");
            Frame(0.125f);
            Assert.That(thing.Position.X, Is.EqualTo(0.125f).Within(1e-6f), "half way between the poses of t=0 and t=0.25");
            Frame(0.125f);
            Assert.That(thing.Position.X, Is.EqualTo(0.25f).Within(1e-6f));
            Assert.That(bridge.World.GetBody(bridge.GetBody(p)).Position.X, Is.EqualTo(0.5f).Within(1e-6f), "the body itself is one step ahead");
        }

        [Test]
        public void Without_interpolation_the_entity_shows_the_last_step()
        {
            using PhysicsBridge bridge = NewBridge(interpolate: false);
            var thing = new Thing("ball", Vector3.Zero);
            ProxyHandle p = bridge.Register(thing, BodyDef.Default, Ball);
            bridge.SetLinearVelocity(p, new Vector3(1, 0, 0));
            bridge.Step(0.375f);
            bridge.SyncToGame();
            Assert.That(thing.Position.X, Is.EqualTo(0.25f).Within(1e-6f));
        }

        [Test]
        public void Game_driven_entity_moves_its_kinematic_body_evenly_over_the_steps_of_a_frame()
        {
            using PhysicsBridge bridge = NewBridge();
            var paddle = new Thing("paddle", Vector3.Zero);
            ProxyHandle p = bridge.Register(paddle, BodyDef.Default, ShapeDef.Of(ShapeGeometry.Box(Vector3.One)), DriveMode.Game);
            BodyHandle body = bridge.GetBody(p);
            Assert.That(bridge.World.GetBody(body).Type, Is.EqualTo(BodyType.Kinematic));

            var stepLog = new List<float>();
            bridge.World.SoftBodyStage = new PositionSpy(bridge.World, body, stepLog);
            paddle.Position = new Vector3(1, 0, 0);
            bridge.SyncFromGame();
            Assert.That(bridge.Step(0.5f), Is.EqualTo(2));
            Assert.That(bridge.World.GetBody(body).Position.X, Is.EqualTo(1f).Within(1e-6f));
            Assert.That(stepLog, Is.EqualTo(new[] { 2f, 2f }).Within(1e-5f), "0.5 m per 0.25 s step, both steps");

            bridge.SyncFromGame();
            bridge.Step(0.25f);
            Assert.That(bridge.World.GetBody(body).Position.X, Is.EqualTo(1f).Within(1e-6f), "it stays where the game left it");
            Assert.That(stepLog[2], Is.EqualTo(0f), "and stops");
        }

        // Reads a body's velocity inside each step (the soft-body stage runs mid-step).
        sealed class PositionSpy : ISoftBodyStage
        {
            readonly World _w; readonly BodyHandle _b; readonly List<float> _log;
            public PositionSpy(World w, BodyHandle b, List<float> log) { _w = w; _b = b; _log = log; }
            public bool HasWork => true;
            public void Step(World world, float dt) => _log.Add(_w.GetBody(_b).LinearVelocity.X);
        }

        sealed class Listener : IBridgeContactListener
        {
            public readonly List<string> Log = new List<string>();
            public Action<BridgeContact>? OnEach;
            public void OnContact(in BridgeContact c)
            {
                Log.Add($"{c.Kind} {c.EntityA} {c.EntityB}");
                OnEach?.Invoke(c);
            }
        }

        static ContactEvent Touch(PhysicsBridge bridge, ProxyHandle a, ProxyHandle b, ContactEventKind kind, float impulse = 1f) => new ContactEvent
        {
            Kind = kind,
            BodyA = bridge.GetBody(a),
            BodyB = bridge.GetBody(b),
            Normal = Vector3.UnitY,
            Point = Vector3.Zero,
            PointCount = kind == ContactEventKind.End ? 0 : 1,
            NormalImpulse = impulse,
        };

        [Test]
        public void Events_are_delivered_after_the_step_in_order_with_the_entities()
        {
            using PhysicsBridge bridge = NewBridge();
            var listener = new Listener();
            bridge.ContactListener = listener;
            ProxyHandle floor = bridge.Register(new Thing("floor", Vector3.Zero), BodyDef.Static(Vector3.Zero), Ball, DriveMode.Game);
            ProxyHandle a = bridge.Register(new Thing("a", new Vector3(0, 10, 0)), BodyDef.Default, Ball);
            ProxyHandle b = bridge.Register(new Thing("b", new Vector3(10, 0, 0)), BodyDef.Default, Ball);
            bridge.InjectContactEvent(Touch(bridge, floor, a, ContactEventKind.Begin));
            bridge.InjectContactEvent(Touch(bridge, floor, b, ContactEventKind.Persist));
            Assert.That(listener.Log, Is.Empty, "nothing before the step");
            bridge.Step(0.25f);
            Assert.That(listener.Log, Is.EqualTo(new[] { "Begin floor a", "Persist floor b" }));
        }

        [Test]
        public void Unregistering_inside_a_callback_is_deferred_and_later_events_for_it_are_skipped()
        {
            using PhysicsBridge bridge = NewBridge();
            var listener = new Listener();
            bridge.ContactListener = listener;
            ProxyHandle floor = bridge.Register(new Thing("floor", Vector3.Zero), BodyDef.Static(Vector3.Zero), Ball, DriveMode.Game);
            ProxyHandle a = bridge.Register(new Thing("a", new Vector3(0, 10, 0)), BodyDef.Default, Ball);
            ProxyHandle b = bridge.Register(new Thing("b", new Vector3(10, 0, 0)), BodyDef.Default, Ball);
            BodyHandle aBody = bridge.GetBody(a);
            ProxyHandle spawned = default;
            int bodiesDuringCallback = -1;
            listener.OnEach = c =>
            {
                if (c.Kind != ContactEventKind.Begin || c.ProxyB != a) return;
                bridge.Unregister(a);
                spawned = bridge.Register(new Thing("spawned", new Vector3(0, 20, 0)), BodyDef.Default, Ball);
                bodiesDuringCallback = bridge.World.BodyCount;
                Assert.Throws<InvalidOperationException>(() => bridge.Step(0.25f));
            };
            bridge.InjectContactEvent(Touch(bridge, floor, a, ContactEventKind.Begin));
            bridge.InjectContactEvent(Touch(bridge, a, b, ContactEventKind.Persist));
            bridge.InjectContactEvent(Touch(bridge, floor, b, ContactEventKind.Persist));
            bridge.Step(0.25f);

            Assert.That(listener.Log, Is.EqualTo(new[] { "Begin floor a", "Persist floor b" }), "a's later event in the batch is skipped");
            Assert.That(bodiesDuringCallback, Is.EqualTo(3), "nothing changed inside the callback");
            Assert.That(bridge.World.IsValid(aBody), Is.False, "removed after the batch");
            Assert.That(bridge.World.BodyCount, Is.EqualTo(3));
            Assert.That(bridge.IsRegistered(spawned), Is.True);
            Assert.That(bridge.GetBody(spawned).IsNone, Is.False, "created after the batch");
            Assert.Throws<StaleHandleException>(() => bridge.GetEntity(a));

            // The end event of a's contacts still names it in the next step.
            listener.Log.Clear();
            var end = new ContactEvent { Kind = ContactEventKind.End, BodyA = bridge.GetBody(floor), BodyB = aBody };
            bridge.InjectContactEvent(end);
            bridge.Step(0.25f);
            Assert.That(listener.Log, Is.EqualTo(new[] { "End floor a" }));

            // Its slot is reused with a new generation; the old handle stays stale.
            ProxyHandle again = bridge.Register(new Thing("again", new Vector3(0, -20, 0)), BodyDef.Default, Ball);
            Assert.That(again, Is.Not.EqualTo(a));
            Assert.That(bridge.IsRegistered(a), Is.False);
        }

        sealed class PointCounter : IBridgeContactListener
        {
            public PhysicsBridge Bridge = null!;
            public int Points = -1;
            public Vector3 Normal;
            public void OnContact(in BridgeContact c)
            {
                if (c.Kind != ContactEventKind.Begin || Points >= 0) return;
                ReadOnlySpan<BridgeContactPoint> points = Bridge.GetPoints(c);
                Points = points.Length;
                Normal = points[0].Normal;
            }
        }

        [Test]
        public void An_unregistered_proxy_slot_is_reused_only_after_a_step_and_the_old_handle_stays_stale()
        {
            using PhysicsBridge bridge = NewBridge();
            ProxyHandle a = bridge.Register(new Thing("a", Vector3.Zero), BodyDef.Default, Ball);
            bridge.Unregister(a);
            ProxyHandle b = bridge.Register(new Thing("b", new Vector3(5, 0, 0)), BodyDef.Default, Ball);
            Assert.That(b.Index, Is.Not.EqualTo(a.Index), "the slot waits for its end events until the next step");
            bridge.Step(0.25f);

            var thing = new Thing("c", new Vector3(-5, 0, 0));
            ProxyHandle c = bridge.Register(thing, BodyDef.Default, Ball);
            Assert.That(c.Index, Is.EqualTo(a.Index), "released after the step, reused first");
            Assert.That(c.Generation, Is.GreaterThan(a.Generation));
            Assert.That(c, Is.Not.EqualTo(a));
            Assert.That(bridge.IsRegistered(a), Is.False);
            Assert.That(() => bridge.GetEntity(a), Throws.TypeOf<StaleHandleException>().With.Message.Contains("it was unregistered"));
            Assert.That(() => bridge.AddForce(a, Vector3.One), Throws.TypeOf<StaleHandleException>());
            Assert.That(bridge.GetEntity(c), Is.SameAs(thing));
            Assert.That(bridge.World.GetBody(bridge.GetBody(c)).Position, Is.EqualTo(thing.Position));
            Assert.That(bridge.Count, Is.EqualTo(2));
            Assert.That(() => bridge.GetEntity(new ProxyHandle(c.Index, c.Generation)), Throws.TypeOf<StaleHandleException>().With.Message.Contains("World 0"),
                "a handle built with no world id");
        }

        [Test]
        public void Contact_events_from_the_world_carry_their_manifold_points()
        {
            WorldSettings ws = WorldSettings.Default;
            PhysicsBridgeSettings s = PhysicsBridgeSettings.Default;
            using var bridge = new PhysicsBridge(new World(ws), s);
            var counter = new PointCounter { Bridge = bridge };
            bridge.ContactListener = counter;
            bridge.Register(new Thing("floor", new Vector3(0, -0.5f, 0)), BodyDef.Static(default), ShapeDef.Of(ShapeGeometry.Box(new Vector3(5, 0.5f, 5))), DriveMode.Game);
            bridge.Register(new Thing("crate", new Vector3(0, 0.6f, 0)), BodyDef.Default, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            for (int k = 0; k < 30 && counter.Points < 0; k++) bridge.Step(1f / 60f);
            Assert.That(counter.Points, Is.EqualTo(4), "face on face");
            Assert.That(MathF.Abs(counter.Normal.Y), Is.EqualTo(1f).Within(1e-5f));
            Assert.Throws<InvalidOperationException>(() => bridge.GetPoints(default));
        }

        [Test]
        public void Haptics_stream_carries_the_mean_contact_force_of_each_step()
        {
            using PhysicsBridge bridge = NewBridge(haptics: 2);
            ProxyHandle floor = bridge.Register(new Thing("floor", Vector3.Zero), BodyDef.Static(Vector3.Zero), Ball, DriveMode.Game);
            ProxyHandle hand = bridge.Register(new Thing("hand", new Vector3(0, 10, 0)), BodyDef.Default, Ball);
            bridge.SetHaptics(hand, true);
            bridge.InjectContactEvent(Touch(bridge, floor, hand, ContactEventKind.Begin, impulse: 2f));
            bridge.Step(0.25f);
            Span<ContactForceSample> read = stackalloc ContactForceSample[4];
            Assert.That(bridge.Haptics!.Read(read), Is.EqualTo(1));
            Assert.That(read[0].Force, Is.EqualTo(new Vector3(0, 8, 0)), "2 N s over 0.25 s");
            Assert.That(read[0].ProxyB, Is.EqualTo(hand));
            Assert.That(read[0].Kind, Is.EqualTo(ContactEventKind.Begin));

            for (int k = 0; k < 3; k++)
            {
                bridge.InjectContactEvent(Touch(bridge, floor, hand, ContactEventKind.Persist, impulse: 1f));
                bridge.Step(0.25f);
            }
            Assert.That(bridge.Haptics.Count, Is.EqualTo(2));
            Assert.That(bridge.Haptics.Dropped, Is.EqualTo(1), "a full ring drops the newest and counts it");
        }

        sealed class ImpulseSum : IBridgeContactListener
        {
            public float Total;
            public void OnContact(in BridgeContact c) => Total += c.NormalImpulse;
        }

        [Test]
        public void A_warm_bridge_frame_allocates_nothing()
        {
            WorldSettings ws = WorldSettings.Default;
            PhysicsBridgeSettings s = PhysicsBridgeSettings.Default;
            using var bridge = new PhysicsBridge(new World(ws), s);
            var sum = new ImpulseSum();
            bridge.ContactListener = sum;
            var proxies = new ProxyHandle[40];
            var things = new Thing[40];
            for (int k = 0; k < proxies.Length; k++)
            {
                things[k] = new Thing("t" + k, new Vector3(k * 2, 0, 0));
                proxies[k] = bridge.Register(things[k], BodyDef.Default, Ball, k % 4 == 0 ? DriveMode.Game : DriveMode.Physics);
                bridge.SetHaptics(proxies[k], true);
            }
            ContactEvent touch = Touch(bridge, proxies[1], proxies[2], ContactEventKind.Persist);
            float t = 0;
            long bytes = AllocationProbe.SteadyStateBytes(() =>
            {
                t += 1f / 60f;
                for (int k = 0; k < things.Length; k += 4) things[k].Position.Y = MathF.Sin(t);
                bridge.InjectContactEvent(touch);
                bridge.AddForce(proxies[3], Vector3.UnitY);
                bridge.SyncFromGame();
                bridge.Step(1f / 60f);
                bridge.SyncToGame();
                bridge.Haptics!.Read(stackalloc ContactForceSample[8]);
            });
            Assert.That(bytes, Is.EqualTo(0));
            Assert.That(sum.Total, Is.GreaterThan(0));
        }

        [Test]
        public void A_physics_thread_at_120_Hz_moves_entities_under_a_60_Hz_game_loop()
        {
            WorldSettings ws = WorldSettings.Default; // gravity on
            PhysicsBridgeSettings s = PhysicsBridgeSettings.Default;
            s.ThreadRateHz = 120;
            var ball = new Thing("ball", new Vector3(0, 10, 0));
            var paddle = new Thing("paddle", new Vector3(5, 0, 0));
            using (var bridge = new PhysicsBridge(new World(ws), s))
            {
                bridge.Register(ball, BodyDef.Default, Ball);
                bridge.Register(paddle, BodyDef.Default, Ball, DriveMode.Game);
                Assert.Throws<InvalidOperationException>(() => _ = bridge.World);
                var clock = System.Diagnostics.Stopwatch.StartNew();
                long before = 0, after = 0;
                while (bridge.ThreadSteps < 40 && clock.Elapsed.TotalSeconds < 5)
                {
                    paddle.Position.X += 0.01f;
                    bridge.SyncFromGame();
                    bridge.Step(1f / 60f);
                    before = bridge.ThreadSteps;
                    bridge.SyncToGame();
                    after = bridge.ThreadSteps;
                    Thread.Sleep(16);
                }
                Assert.That(bridge.ThreadSteps, Is.GreaterThanOrEqualTo(40), "the thread kept stepping");
                // Semi-implicit Euler from rest: y_n = 10 - g dt^2 n (n + 1) / 2. The pose shown
                // blends steps of a publication made before `after`, and the ball joined the
                // thread's step count a few steps late (its creation waits for the next tick).
                const float dt = 1f / 120f;
                float Y(long n) => 10f - 9.81f * dt * dt * n * (n + 1) / 2f;
                Assert.That(ball.Position.Y, Is.GreaterThanOrEqualTo(Y(after) - 1e-3f), "never ahead of the thread");
                Assert.That(ball.Position.Y, Is.LessThan(Y(before / 2)), "and not stuck: at least half the steps shown");
            }
            Assert.That(paddle.Position.X, Is.GreaterThan(5.1f), "game-driven poses are the game's");
        }

        [Test]
        public void Bad_registrations_and_calls_throw_naming_the_entity_and_field()
        {
            using PhysicsBridge bridge = NewBridge();
            Assert.Throws<ArgumentNullException>(() => bridge.Register(null!, BodyDef.Default, Ball));
            var nan = new Thing("broken", new Vector3(float.NaN, 0, 0));
            var ex = Assert.Throws<ArgumentException>(() => bridge.Register(nan, BodyDef.Default, Ball))!;
            Assert.That(ex.Message, Does.Contain("broken: position must be finite"));
            var plane = ShapeDef.Of(ShapeGeometry.Plane(Vector3.UnitY, 0));
            ex = Assert.Throws<ArgumentException>(() => bridge.Register(new Thing("ground", Vector3.Zero), BodyDef.Default, plane))!;
            Assert.That(ex.Message, Does.Contain("ground shapes[0] is a Plane"));
            ex = Assert.Throws<ArgumentException>(() => bridge.Register(new Thing("wall", Vector3.Zero), BodyDef.Static(Vector3.Zero), Ball, DriveMode.Physics))!;
            Assert.That(ex.Message, Does.Contain("wall has a static body"));
            Assert.That(bridge.Count, Is.EqualTo(0));
            Assert.That(bridge.World.BodyCount, Is.EqualTo(0), "nothing was half-created");

            ProxyHandle p = bridge.Register(new Thing("ok", Vector3.Zero), BodyDef.Default, Ball);
            Assert.Throws<ArgumentException>(() => bridge.AddForce(p, new Vector3(float.NaN, 0, 0)));
            bridge.Unregister(p);
            Assert.Throws<StaleHandleException>(() => bridge.Unregister(p));
            Assert.Throws<StaleHandleException>(() => bridge.AddForce(default, Vector3.One));
        }
    }
}
