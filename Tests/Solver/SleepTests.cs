using System.Numerics;
using Fulcrum;
using NUnit.Framework;
using static Fulcrum.Tests.Solver.SolverTestScenes;

namespace Fulcrum.Tests.Solver
{
    /// <summary>Islands fall asleep together and wake together.</summary>
    public class SleepTests
    {
        const float Dt = 1f / 60f;

        static (World w, BodyHandle[] links) RestingChain(int count)
        {
            var w = new World();
            var links = new BodyHandle[count];
            BodyHandle prev = BodyHandle.None;
            Vector3 anchor = Vector3.Zero;
            for (int i = 0; i < count; i++)
            {
                links[i] = Box(w, new Vector3(0, -0.5f - i, 0), new Vector3(0.1f, 0.5f, 0.1f), 1f);
                w.CreateJoint(JointDef.Ball(prev, links[i], anchor, new Vector3(0, 0.5f, 0)));
                prev = links[i];
                anchor = new Vector3(0, -0.5f, 0);
            }
            return (w, links);
        }

        [Test]
        public void A_resting_jointed_island_falls_asleep_after_TimeToSleep_and_then_costs_no_solver_work()
        {
            var (w, links) = RestingChain(5);
            int steps = 0;
            while (w.AwakeBodyCount > 0 && steps < 300) { w.Step(Dt); steps++; }
            Assert.That(w.AwakeBodyCount, Is.EqualTo(0));
            // Asleep after the rest time (0.5 s) and not much later.
            Assert.That(steps * Dt, Is.EqualTo(0.5f).Within(0.1f));
            Vector3 p = w.GetBody(links[4]).Position;
            for (int n = 0; n < 60; n++) w.Step(Dt);
            Assert.That(w.GetBody(links[4]).Position, Is.EqualTo(p));
            Assert.That(w.LastStepProfile.Solve, Is.LessThan(0.5));
        }

        [Test]
        public void A_force_on_one_body_wakes_its_whole_island()
        {
            var (w, links) = RestingChain(5);
            for (int n = 0; n < 60; n++) w.Step(Dt);
            Assert.That(w.AwakeBodyCount, Is.EqualTo(0));
            w.AddForce(links[2], new Vector3(50, 0, 0));
            Assert.That(w.AwakeBodyCount, Is.EqualTo(5));
            w.Step(Dt);
            Assert.That(w.GetBody(links[2]).LinearVelocity.X, Is.GreaterThan(0f));
            // The push reaches the end of the chain in the same step.
            Assert.That(w.GetBody(links[4]).LinearVelocity.Length(), Is.GreaterThan(1e-3f));
        }

        [Test]
        public void A_new_joint_to_a_sleeping_body_wakes_it()
        {
            var (w, links) = RestingChain(3);
            for (int n = 0; n < 60; n++) w.Step(Dt);
            BodyHandle weight = Sphere(w, new Vector3(0, -3.5f, 0), 0.2f, 5f);
            w.CreateJoint(JointDef.Ball(links[2], weight, new Vector3(0, -0.5f, 0), new Vector3(0, 0.5f, 0)));
            Assert.That(w.AwakeBodyCount, Is.EqualTo(4));
        }

        [Test]
        public void Destroying_a_joint_wakes_the_body_it_held()
        {
            var (w, links) = RestingChain(3);
            for (int n = 0; n < 60; n++) w.Step(Dt);
            Assert.That(w.AwakeBodyCount, Is.EqualTo(0));
            w.DestroyBody(links[0]);
            Assert.That(w.GetBody(links[1]).IsAwake, Is.True);
            Assert.That(w.GetBody(links[2]).IsAwake, Is.True);
            float y = w.GetBody(links[2]).Position.Y;
            for (int n = 0; n < 30; n++) w.Step(Dt);
            Assert.That(w.GetBody(links[2]).Position.Y, Is.LessThan(y - 1f));
        }

        [Test]
        public void A_body_that_may_not_sleep_keeps_its_island_awake()
        {
            var (w, links) = RestingChain(3);
            w.GetBody(links[1]).AllowSleep = false;
            for (int n = 0; n < 120; n++) w.Step(Dt);
            Assert.That(w.AwakeBodyCount, Is.EqualTo(3));
        }
    }
}
