using System;
using System.Numerics;
using Fulcrum;
using NUnit.Framework;
using static Fulcrum.Tests.Solver.SolverTestScenes;

namespace Fulcrum.Tests.Solver
{
    /// <summary>Joint scenes against closed forms: pendulum period, motor speed, spring period, limits, loads.</summary>
    public class JointSceneTests
    {
        const float Dt = 1f / 60f;
        const float G = 9.81f;

        // A thin rod hung from one end by a ball joint: T = 2 pi sqrt(I_pivot / (m g d)) with
        // I_pivot = m/3 (a^2 + h^2) + m h^2 and d = h, times (1 + theta0^2 / 16) for the amplitude.
        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void Rod_pendulum_on_a_ball_joint_swings_with_the_closed_form_period_and_keeps_its_energy(SolverType solver)
        {
            var w = new World(Settings(solver));
            const float h = 0.5f, a = 0.02f, theta0 = 0.1f;
            Quaternion tilt = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, theta0);
            Vector3 center = Vector3.Transform(new Vector3(0, -h, 0), tilt);
            BodyHandle rod = Box(w, center, new Vector3(a, h, a), 1f, tilt);
            w.CreateJoint(JointDef.Ball(BodyHandle.None, rod, Vector3.Zero, new Vector3(0, h, 0)));
            double iPivot = (a * a + h * h) / 3.0 + h * h;
            double expected = 2 * Math.PI * Math.Sqrt(iPivot / (G * h)) * (1 + theta0 * theta0 / 16);
            float e0 = Energy(w, rod);

            double first = -1, last = -1;
            int crossings = 0;
            float prevX = center.X, energy = e0;
            for (int n = 1; n <= 720; n++)
            {
                w.Step(Dt);
                float x = w.GetBody(rod).CenterOfMass.X;
                if (prevX > 0 && x <= 0)
                {
                    double t = (n - 1 + prevX / (prevX - x)) * Dt;
                    if (first < 0) first = t;
                    last = t;
                    crossings++;
                }
                prevX = x;
                energy = Energy(w, rod);
            }
            double period = (last - first) / (crossings - 1);
            TestContext.Out.WriteLine($"{solver}: period {period:F5} s (closed form {expected:F5} s), energy after 12 s {energy / e0:F5} of start, joint error {w.MaxJointError:E2} m");
            Assert.That(period, Is.EqualTo(expected).Within(0.002 * expected));
            Assert.That(energy, Is.EqualTo(e0).Within(0.01f * e0));
            Assert.That(w.MaxJointError, Is.LessThan(1e-3f));
        }

        // A small sphere far from its anchor: K of the anchor point is 1000:1 anisotropic
        // (tangential 1/m + L^2/I against radial 1/m), which punishes a stale effective mass.
        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void Small_ball_on_a_long_ball_joint_arm_keeps_its_energy(SolverType solver)
        {
            var w = new World(Settings(solver));
            const float L = 1f, theta0 = 0.1f;
            var start = new Vector3(L * MathF.Sin(theta0), -L * MathF.Cos(theta0), 0);
            BodyHandle ball = Sphere(w, start, 0.05f, 1f);
            w.CreateJoint(JointDef.Ball(BodyHandle.None, ball, Vector3.Zero, -start));
            float e0 = Energy(w, ball), emax = e0;
            for (int n = 0; n < 1800; n++)
            {
                w.Step(Dt);
                emax = MathF.Max(emax, Energy(w, ball));
            }
            TestContext.Out.WriteLine($"{solver}: energy after 30 s {Energy(w, ball) / e0:F4}, highest {emax / e0:F4} of start");
            Assert.That(emax, Is.LessThan(1.01f * e0));
            Assert.That(Energy(w, ball), Is.GreaterThan(0.97f * e0));
        }

        static int Substeps(World w) => w.Settings.Solver == SolverType.Tgs ? w.Settings.Substeps : 1;

        static float Energy(World w, BodyHandle b)
        {
            BodyRef r = w.GetBody(b);
            return r.KineticEnergy + r.Mass * G * r.CenterOfMass.Y + 10f;
        }

        static (World world, BodyHandle load, Vector3 start) HangingChain(WorldSettings settings, int links, float loadMass)
        {
            var w = new World(settings);
            const float half = 0.25f;
            BodyHandle prev = BodyHandle.None;
            Vector3 prevAnchor = Vector3.Zero;
            for (int i = 0; i < links; i++)
            {
                BodyHandle link = Box(w, new Vector3(0, -half - 2 * half * i, 0), new Vector3(0.05f, half, 0.05f), 1f);
                w.CreateJoint(JointDef.Ball(prev, link, prevAnchor, new Vector3(0, half, 0)));
                prev = link;
                prevAnchor = new Vector3(0, -half, 0);
            }
            var start = new Vector3(0, -2 * half * links - 0.25f, 0);
            BodyHandle load = Box(w, start, new Vector3(0.25f), loadMass);
            w.CreateJoint(JointDef.Ball(prev, load, prevAnchor, new Vector3(0, 0.25f, 0)));
            return (w, load, start);
        }

        // A joint row is a spring of JointHertz (here as stiff as the substep allows: a quarter of
        // the substep rate) on the effective mass it holds. Solved as one block (joint trees) that
        // mass is the tree's own, the load's, and the whole chain sags g / omega^2: 0.069, 0.017
        // and 0.004 mm at 4, 8 and 16 substeps. Row by row it was the 1 kg link's: the chain
        // stretched 3.5 %, 1 % and 0.25 % of its 5 m.
        [TestCase(4, 4)]
        [TestCase(8, 1)]
        [TestCase(16, 1)]
        public void Chain_of_ten_1kg_links_holds_a_100kg_weight(int substeps, int iterations)
        {
            WorldSettings s = WorldSettings.Default;
            s.Substeps = substeps;
            s.Iterations = iterations;
            s.JointHertz = 1000f; // as stiff as each substep allows
            s.EnableSleeping = false;
            var (w, load, start) = HangingChain(s, 10, 100f);
            float worst = 0;
            for (int n = 0; n < 300; n++)
            {
                w.Step(Dt);
                if (n >= 120) worst = MathF.Max(worst, start.Y - w.GetBody(load).Position.Y);
            }
            float stretch = start.Y - w.GetBody(load).Position.Y;
            float speed = w.GetBody(load).LinearVelocity.Length();
            TestContext.Out.WriteLine($"TGS {substeps}x{iterations}: stretch after 5 s {stretch * 1000:F3} mm ({stretch / 5f * 100:F4} % of 5 m; worst after 2 s {worst * 1000:F3} mm), load speed {speed:E1} m/s");
            double omega = 2 * Math.PI * Math.Min(1000.0, 0.25 * 60 * substeps);
            double expected = G / (omega * omega);
            Assert.That(stretch, Is.EqualTo(expected).Within(0.15 * expected + 2e-6));
            Assert.That(worst, Is.LessThan(2 * expected + 2e-6));
            Assert.That(speed, Is.LessThan(0.01f));
        }

        [Test]
        public void Ball_joint_reports_the_force_that_holds_a_hanging_body()
        {
            var w = new World();
            BodyHandle body = Sphere(w, new Vector3(0, -1, 0), 0.1f, 2f);
            JointHandle j = w.CreateJoint(JointDef.Ball(BodyHandle.None, body, Vector3.Zero, new Vector3(0, 1, 0)));
            for (int n = 0; n < 60; n++) w.Step(Dt);
            Vector3 f = w.GetJointForce(j);
            Assert.That(f.Y, Is.EqualTo(2f * G).Within(0.01f * 2f * G));
            Assert.That(MathF.Abs(f.X) + MathF.Abs(f.Z), Is.LessThan(1e-3f));
            Assert.That(w.GetJointTorque(j).Length(), Is.LessThan(1e-4f));
            Assert.That(w.GetJointStress(j), Is.EqualTo(0f));
        }

        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void Breakable_joint_breaks_once_when_the_load_goes_over_its_threshold(SolverType solver)
        {
            var w = new World(Settings(solver));
            BodyHandle body = Sphere(w, new Vector3(0, -1, 0), 0.1f, 1f);
            JointDef def = JointDef.Ball(BodyHandle.None, body, Vector3.Zero, new Vector3(0, 1, 0));
            def.BreakForce = 20f;
            def.UserData = 42;
            JointHandle j = w.CreateJoint(def);
            for (int n = 0; n < 60; n++)
            {
                w.Step(Dt);
                Assert.That(w.JointBreakEvents.Length, Is.EqualTo(0));
            }
            Assert.That(w.GetJointStress(j), Is.EqualTo(G / 20f).Within(0.02f * G / 20f));

            int breaks = 0;
            JointBreakEvent e = default;
            for (int n = 0; n < 60; n++)
            {
                w.AddForce(body, new Vector3(0, -15f, 0)); // 24.8 N in all
                w.Step(Dt);
                if (w.JointBreakEvents.Length > 0) e = w.JointBreakEvents[0];
                breaks += w.JointBreakEvents.Length;
            }
            Assert.That(breaks, Is.EqualTo(1));
            Assert.That(e.Joint, Is.EqualTo(j));
            Assert.That(e.BodyB, Is.EqualTo(body));
            Assert.That(e.UserData, Is.EqualTo(42UL));
            Assert.That(e.Stress, Is.GreaterThan(1f));
            Assert.That(e.Force.Length(), Is.EqualTo(24.81f).Within(0.5f));
            Assert.That(w.IsJointBroken(j), Is.True);
            // Broken: the body falls freely.
            Assert.That(w.GetBody(body).Position.Y, Is.LessThan(-2f));
        }

        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void Hinge_motor_spins_a_wheel_up_to_its_speed_with_bounded_torque(SolverType solver)
        {
            WorldSettings s = Settings(solver);
            s.Gravity = Vector3.Zero;
            var w = new World(s);
            BodyHandle wheel = Box(w, Vector3.Zero, new Vector3(0.5f, 0.5f, 0.1f), 6f);
            float iz = 6f / 3f * (0.25f + 0.25f); // 1 kg m^2 about z
            JointDef d = JointDef.Hinge(BodyHandle.None, wheel, Vector3.Zero, Vector3.Zero, Vector3.UnitZ, Vector3.UnitZ);
            d.MotorSpeed = 3f;
            d.MaxMotorTorque = 2f;
            JointHandle j = w.CreateJoint(d);
            // The torque limit gives alpha = 2 rad/s^2: 1 s in, w = 2 rad/s.
            for (int n = 0; n < 60; n++) w.Step(Dt);
            Assert.That(w.GetBody(wheel).AngularVelocity.Z, Is.EqualTo(2f / iz).Within(0.02f));
            for (int n = 0; n < 60; n++) w.Step(Dt);
            Assert.That(w.GetBody(wheel).AngularVelocity.Z, Is.EqualTo(3f).Within(0.01f));
            Assert.That(w.GetBody(wheel).AngularVelocity.X, Is.EqualTo(0f).Within(1e-4f));
            Assert.That(w.GetJointError(j), Is.LessThan(1e-4f));
        }

        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void Hinge_limit_stops_a_falling_plank_at_the_limit_angle(SolverType solver)
        {
            var w = new World(Settings(solver));
            // A plank hinged at its left end about z swings down under gravity until -30 degrees.
            BodyHandle plank = Box(w, new Vector3(1, 0, 0), new Vector3(1, 0.05f, 0.1f), 2f);
            JointDef d = JointDef.Hinge(BodyHandle.None, plank, Vector3.Zero, new Vector3(-1, 0, 0), Vector3.UnitZ, Vector3.UnitZ);
            d.LowerDeg = -30;
            d.UpperDeg = 45;
            JointHandle j = w.CreateJoint(d);
            float lowest = 0;
            for (int n = 0; n < 180; n++)
            {
                w.Step(Dt);
                lowest = MathF.Min(lowest, w.GetJointAngle(j));
            }
            float angle = w.GetJointAngle(j) * 180f / MathF.PI;
            TestContext.Out.WriteLine($"{solver}: rests at {angle:F3} deg, lowest {lowest * 180f / MathF.PI:F3} deg");
            Assert.That(angle, Is.EqualTo(-30f).Within(0.5f));
            Assert.That(lowest * 180f / MathF.PI, Is.GreaterThan(-32f));
        }

        [Test]
        public void Hinge_spring_oscillates_at_its_frequency()
        {
            WorldSettings s = WorldSettings.Default;
            s.Gravity = Vector3.Zero;
            var w = new World(s);
            BodyHandle wheel = Box(w, Vector3.Zero, new Vector3(0.5f, 0.5f, 0.1f), 6f);
            JointDef d = JointDef.Hinge(BodyHandle.None, wheel, Vector3.Zero, Vector3.Zero, Vector3.UnitZ, Vector3.UnitZ);
            d.StiffnessHz = 2f;
            JointHandle j = w.CreateJoint(d);
            w.GetBody(wheel).AngularVelocity = new Vector3(0, 0, 1f);
            double first = -1, last = -1;
            int crossings = 0;
            float prev = 0;
            for (int n = 1; n <= 240; n++)
            {
                w.Step(Dt);
                float a = w.GetJointAngle(j);
                if (prev > 0 && a <= 0)
                {
                    double t = (n - 1 + prev / (prev - a)) * Dt;
                    if (first < 0) first = t;
                    last = t;
                    crossings++;
                }
                prev = a;
            }
            double period = (last - first) / (crossings - 1);
            Assert.That(crossings, Is.GreaterThanOrEqualTo(7));
            Assert.That(period, Is.EqualTo(0.5).Within(0.01));
        }

        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void Rope_is_slack_below_its_length_and_taut_at_it(SolverType solver)
        {
            var w = new World(Settings(solver));
            BodyHandle ball = Sphere(w, new Vector3(0, -1, 0), 0.1f, 1f);
            JointHandle rope = w.CreateJoint(JointDef.Distance(BodyHandle.None, ball, Vector3.Zero, Vector3.Zero, 0f, 2f));
            // Slack: free fall for the first metre (semi-implicit Euler over N (sub)steps falls
            // 1/2 g t^2 (1 + 1/N)).
            for (int n = 0; n < 20; n++) w.Step(Dt);
            float t = 20 * Dt;
            float fall = 0.5f * G * t * t * (1f + 1f / (20 * Substeps(w)));
            Assert.That(w.GetBody(ball).Position.Y, Is.EqualTo(-1f - fall).Within(1e-3f));
            for (int n = 0; n < 240; n++) w.Step(Dt);
            Assert.That(w.GetBody(ball).Position.Length(), Is.EqualTo(2f).Within(0.005f));
            Assert.That(w.GetJointError(rope), Is.LessThan(0.005f));
        }

        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void Distance_rod_keeps_a_swinging_ball_at_its_length(SolverType solver)
        {
            var w = new World(Settings(solver));
            BodyHandle ball = Sphere(w, new Vector3(1.5f, 0, 0), 0.1f, 1f);
            w.CreateJoint(JointDef.Distance(BodyHandle.None, ball, Vector3.Zero, Vector3.Zero, -1, -1));
            float worst = 0;
            for (int n = 0; n < 240; n++)
            {
                w.Step(Dt);
                worst = MathF.Max(worst, MathF.Abs(w.GetBody(ball).Position.Length() - 1.5f));
            }
            Assert.That(worst, Is.LessThan(0.01f));
        }

        [Test]
        public void Distance_spring_hangs_at_its_static_stretch_mg_over_k()
        {
            var w = new World();
            const float m = 2f, hz = 1.5f;
            BodyHandle ball = Sphere(w, new Vector3(0, -1, 0), 0.1f, m);
            JointDef d = JointDef.Distance(BodyHandle.None, ball, Vector3.Zero, Vector3.Zero, -1, -1);
            d.StiffnessHz = hz;
            d.Damping = 1f;
            w.CreateJoint(d);
            for (int n = 0; n < 600; n++) w.Step(Dt);
            // k = m (2 pi f)^2 for a spring on one body: x = m g / k = g / (2 pi f)^2.
            float omega = 2 * MathF.PI * hz;
            Assert.That(w.GetBody(ball).Position.Y, Is.EqualTo(-1f - G / (omega * omega)).Within(0.002f));
        }

        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void Prismatic_joint_slides_along_its_axis_down_to_its_limit(SolverType solver)
        {
            var w = new World(Settings(solver));
            // A 45-degree rail: the body slides down without turning and stops 1 m along.
            Vector3 axis = Vector3.Normalize(new Vector3(1, -1, 0));
            BodyHandle body = Box(w, Vector3.Zero, new Vector3(0.2f), 1f);
            JointDef d = JointDef.Prismatic(BodyHandle.None, body, Vector3.Zero, Vector3.Zero, axis);
            d.Lower = -0.5f;
            d.Upper = 1f;
            JointHandle j = w.CreateJoint(d);
            for (int n = 0; n < 20; n++) w.Step(Dt);
            float t = 20 * Dt;
            float along = Vector3.Dot(w.GetBody(body).Position, axis);
            Assert.That(along, Is.EqualTo(0.5f * G * MathF.Sin(MathF.PI / 4) * t * t * (1f + 1f / (20 * Substeps(w)))).Within(2e-3f));
            for (int n = 0; n < 120; n++) w.Step(Dt);
            Vector3 p = w.GetBody(body).Position;
            Assert.That(Vector3.Dot(p, axis), Is.EqualTo(1f).Within(0.01f));
            Assert.That((p - Vector3.Dot(p, axis) * axis).Length(), Is.LessThan(0.002f));
            Assert.That(w.GetBody(body).AngularVelocity.Length(), Is.LessThan(1e-3f));
            Assert.That(Quaternion.Dot(w.GetBody(body).Rotation, Quaternion.Identity), Is.GreaterThan(0.99999f));
            Assert.That(w.GetJointError(j), Is.LessThan(0.01f));
        }

        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void Cone_twist_joint_keeps_a_kicked_limb_inside_its_cone(SolverType solver)
        {
            WorldSettings s = Settings(solver);
            s.Gravity = Vector3.Zero;
            var w = new World(s);
            // A limb hanging along -y from a fixed socket, twist axis along the limb; kicked sideways.
            BodyHandle limb = Box(w, new Vector3(0, -0.5f, 0), new Vector3(0.05f, 0.5f, 0.05f), 1f);
            w.CreateJoint(JointDef.ConeTwist(BodyHandle.None, limb, Vector3.Zero, new Vector3(0, 0.5f, 0), -Vector3.UnitY, -Vector3.UnitY, 30f, 20f));
            w.GetBody(limb).AngularVelocity = new Vector3(3f, 4f, 2f);
            float worstSwing = 0;
            for (int n = 0; n < 180; n++)
            {
                w.Step(Dt);
                Vector3 axis = Vector3.Transform(-Vector3.UnitY, w.GetBody(limb).Rotation);
                worstSwing = MathF.Max(worstSwing, MathF.Acos(Math.Clamp(Vector3.Dot(axis, -Vector3.UnitY), -1f, 1f)));
            }
            TestContext.Out.WriteLine($"{solver}: largest swing {worstSwing * 180 / MathF.PI:F2} deg");
            Assert.That(worstSwing * 180f / MathF.PI, Is.LessThan(31.5f));
            Assert.That(worstSwing * 180f / MathF.PI, Is.GreaterThan(25f));
        }

        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void Fixed_joint_holds_a_cantilever_still(SolverType solver)
        {
            var w = new World(Settings(solver));
            BodyHandle beam = Box(w, new Vector3(1, 0, 0), new Vector3(1, 0.1f, 0.1f), 5f);
            JointHandle j = w.CreateJoint(JointDef.Fixed(BodyHandle.None, beam, Vector3.Zero, new Vector3(-1, 0, 0)));
            for (int n = 0; n < 120; n++) w.Step(Dt);
            BodyRef b = w.GetBody(beam);
            Assert.That(Vector3.Distance(b.Position, new Vector3(1, 0, 0)), Is.LessThan(0.01f));
            Assert.That(MathF.Abs(Quaternion.Dot(b.Rotation, Quaternion.Identity)), Is.GreaterThan(0.9999f));
            // Holding a 5 kg beam by one end: 49 N up and a 49 N m torque.
            Assert.That(w.GetJointForce(j).Y, Is.EqualTo(5f * G).Within(0.5f));
            Assert.That(w.GetJointTorque(j).Z, Is.EqualTo(5f * G * 1f).Within(1f));
        }
    
        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void Prismatic_motor_drives_a_slider_at_its_speed(SolverType solver)
        {
            var w = new World(Settings(solver));
            BodyHandle body = Box(w, Vector3.Zero, new Vector3(0.2f), 2f);
            JointDef d = JointDef.Prismatic(BodyHandle.None, body, Vector3.Zero, Vector3.Zero, Vector3.UnitY);
            d.MotorSpeed = 0.5f;
            d.MaxMotorForce = 100f; // beats the 19.6 N weight
            w.CreateJoint(d);
            for (int n = 0; n < 60; n++) w.Step(Dt);
            Assert.That(w.GetBody(body).LinearVelocity.Y, Is.EqualTo(0.5f).Within(0.005f));
            Assert.That(w.GetBody(body).Position.Y, Is.EqualTo(0.5f).Within(0.03f));
        }
}
}
