using System;
using System.Numerics;
using Fulcrum;
using NUnit.Framework;
using static Fulcrum.Tests.Solver.SolverTestScenes;

namespace Fulcrum.Tests.Solver
{
    /// <summary>Contacts against closed forms: friction on slopes, restitution, speculative contacts.</summary>
    public class ContactSceneTests
    {
        const float Dt = 1f / 60f;
        const float G = 9.81f;

        // A 0.5 m cube resting on a static slope (a big box turned about z), its face on the slope.
        static (World w, BodyHandle box, Vector3 down) BoxOnSlope(SolverType solver, float degrees, float mu)
        {
            var w = new World(Settings(solver));
            float a = degrees * MathF.PI / 180f;
            Quaternion tilt = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, a);
            Vector3 normal = Vector3.Transform(Vector3.UnitY, tilt);
            Vector3 down = Vector3.Transform(-Vector3.UnitX, tilt); // down the slope
            StaticBox(w, -0.5f * normal, new Vector3(30, 0.5f, 5), tilt, mu);
            BodyHandle box = Box(w, 0.25f * normal, new Vector3(0.25f), 2f, tilt, mu);
            return (w, box, down);
        }

        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void Box_on_30deg_slope_with_mu_0_7_stays_put(SolverType solver)
        {
            var (w, box, down) = BoxOnSlope(solver, 30, 0.7f);
            WorldSettings s = w.Settings;
            s.EnableSleeping = false; // measure the creep itself, not a sleeping body
            w.Settings = s;
            Vector3 start = w.GetBody(box).Position;
            for (int n = 0; n < 600; n++) w.Step(Dt);
            float moved = Vector3.Dot(w.GetBody(box).Position - start, down);
            TestContext.Out.WriteLine($"{solver}: moved {moved * 1000:F4} mm down the slope in 10 s");
            Assert.That(MathF.Abs(moved), Is.LessThan(0.001f));
        }

        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void Box_sliding_down_30deg_slope_with_mu_0_2_accelerates_at_g_sin_minus_mu_cos(SolverType solver)
        {
            var (w, box, down) = BoxOnSlope(solver, 30, 0.2f);
            float expected = G * (MathF.Sin(MathF.PI / 6) - 0.2f * MathF.Cos(MathF.PI / 6));
            for (int n = 0; n < 30; n++) w.Step(Dt);
            float v0 = Vector3.Dot(w.GetBody(box).LinearVelocity, down);
            for (int n = 0; n < 60; n++) w.Step(Dt);
            float v1 = Vector3.Dot(w.GetBody(box).LinearVelocity, down);
            float a = (v1 - v0) / (60 * Dt);
            TestContext.Out.WriteLine($"{solver}: a = {a:F4} m/s^2, closed form {expected:F4} m/s^2 ({(a / expected - 1) * 100:F2} %)");
            Assert.That(a, Is.EqualTo(expected).Within(0.02f * expected));
            Assert.That(w.GetBody(box).AngularVelocity.Length(), Is.LessThan(0.01f));
        }

        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void Ball_with_restitution_0_5_bounces_to_a_quarter_of_its_drop_height_and_comes_to_rest(SolverType solver)
        {
            var w = new World(Settings(solver));
            Ground(w, restitution: 0.5f);
            // Semi-implicit Euler at 60 Hz loses about v dt / 2 of the apex (the integrator, not
            // the contact): 2 % from 8 m, where e^2 h is 2 m.
            const float r = 0.25f, h = 8f;
            BodyHandle ball = Sphere(w, new Vector3(0, h + r, 0), r, 1f, restitution: 0.5f);
            bool bounced = false;
            float apex = 0, prevVy = 0;
            int n = 0;
            for (; n < 900 && apex == 0; n++)
            {
                w.Step(Dt);
                float vy = w.GetBody(ball).LinearVelocity.Y;
                if (vy > 0) bounced = true;
                if (bounced && prevVy > 0 && vy <= 0) apex = w.GetBody(ball).Position.Y - r;
                prevVy = vy;
            }
            float expected = 0.25f * h;
            TestContext.Out.WriteLine($"{solver}: first apex {apex:F4} m, e^2 h = {expected:F4} m ({(apex / expected - 1) * 100:F2} %)");
            Assert.That(apex, Is.EqualTo(expected).Within(0.05f * expected));
            for (; n < 900; n++) w.Step(Dt);
            Assert.That(w.GetBody(ball).LinearVelocity.Length(), Is.LessThan(1e-3f));
            Assert.That(w.GetBody(ball).Position.Y, Is.EqualTo(r).Within(0.01f));
        }

        [Test]
        public void Resting_body_with_restitution_1_never_bounces()
        {
            var w = new World();
            Ground(w, restitution: 1f);
            BodyHandle ball = Sphere(w, new Vector3(0, 0.25f + 0.01f, 0), 0.25f, 1f, restitution: 1f);
            float highest = 0;
            for (int n = 0; n < 120; n++)
            {
                w.Step(Dt);
                highest = MathF.Max(highest, w.GetBody(ball).Position.Y - 0.25f);
                if (n > 30) Assert.That(w.GetBody(ball).LinearVelocity.Y, Is.LessThan(0.05f));
            }
            Assert.That(highest, Is.LessThan(0.011f));
        }

        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void Fast_ball_meets_a_thin_wall_speculatively_and_does_not_pass(SolverType solver)
        {
            WorldSettings s = Settings(solver);
            s.Gravity = Vector3.Zero;
            var w = new World(s);
            StaticBox(w, new Vector3(2, 0, 0), new Vector3(0.05f, 2, 2));
            BodyHandle ball = Sphere(w, Vector3.Zero, 0.1f, 1f);
            w.GetBody(ball).LinearVelocity = new Vector3(60, 0, 0); // 1 m per step, the wall is 10 cm thick
            for (int n = 0; n < 10; n++) w.Step(Dt);
            float x = w.GetBody(ball).Position.X;
            Assert.That(x, Is.LessThan(1.95f - 0.1f + 0.01f));
            Assert.That(x, Is.GreaterThan(1.5f));
        }

        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void Pushed_box_stays_below_mu_m_g_and_slides_above_it(SolverType solver)
        {
            var w = new World(Settings(solver));
            Ground(w, friction: 0.5f);
            BodyHandle box = Box(w, new Vector3(0, 0.5f, 0), new Vector3(0.5f), 10f, friction: 0.5f);
            for (int n = 0; n < 30; n++) w.Step(Dt);
            float x0 = w.GetBody(box).Position.X;
            for (int n = 0; n < 60; n++)
            {
                w.AddForce(box, new Vector3(0.9f * 0.5f * 10f * G, 0, 0));
                w.Step(Dt);
            }
            Assert.That(w.GetBody(box).Position.X - x0, Is.LessThan(1e-3f));
            // Above the limit: a = (F - mu m g) / m.
            const float f = 80f;
            for (int n = 0; n < 30; n++) { w.AddForce(box, new Vector3(f, 0, 0)); w.Step(Dt); }
            float v0 = w.GetBody(box).LinearVelocity.X;
            for (int n = 0; n < 60; n++) { w.AddForce(box, new Vector3(f, 0, 0)); w.Step(Dt); }
            float a = (w.GetBody(box).LinearVelocity.X - v0) / (60 * Dt);
            float expected = (f - 0.5f * 10f * G) / 10f;
            Assert.That(a, Is.EqualTo(expected).Within(0.02f * expected));
        }

        [Test]
        public void Block_and_sequential_normal_rows_agree_on_a_resting_box()
        {
            foreach (bool block in new[] { false, true })
            {
                WorldSettings s = WorldSettings.Default;
                s.BlockSolver = block;
                s.EnableSleeping = false;
                var w = new World(s);
                Ground(w);
                BodyHandle box = Box(w, new Vector3(0, 0.5f, 0), new Vector3(0.5f), 4f);
                for (int n = 0; n < 120; n++) w.Step(Dt);
                ref Fulcrum.Collision.ContactManifold m = ref w.Contacts[0];
                Assert.That(m.PointCount, Is.EqualTo(4));
                for (int i = 0; i < 4; i++)
                    Assert.That(Fulcrum.Collision.ContactManifold.Point(ref m, i).NormalImpulse, Is.EqualTo(G * Dt).Within(0.002f * G * Dt), $"block={block}");
                Assert.That(w.GetBody(box).LinearVelocity.Length(), Is.LessThan(1e-4f));
            }
        }
    
        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void Kinematic_platform_lifts_and_carries_a_box(SolverType solver)
        {
            var w = new World(Settings(solver));
            BodyHandle platform = w.CreateBody(BodyDef.Kinematic(new Vector3(0, -0.1f, 0)));
            w.AddShape(platform, ShapeDef.Of(ShapeGeometry.Box(new Vector3(2, 0.1f, 2))));
            BodyHandle box = Box(w, new Vector3(0, 0.25f, 0), new Vector3(0.25f), 1f);
            for (int n = 0; n < 30; n++) w.Step(Dt);
            w.GetBody(platform).LinearVelocity = new Vector3(0.5f, 1f, 0);
            for (int n = 0; n < 60; n++) w.Step(Dt);
            BodyRef b = w.GetBody(box);
            // One second at (0.5, 1) m/s: the box rides along, on top of the platform.
            Assert.That(b.Position.Y, Is.EqualTo(1.25f).Within(0.01f));
            Assert.That(b.Position.X, Is.EqualTo(0.5f).Within(0.01f));
            Assert.That(b.LinearVelocity.Y, Is.EqualTo(1f).Within(0.01f));
        }
}
}
