using System;
using System.Numerics;
using Fulcrum;
using NUnit.Framework;
using static Fulcrum.Tests.Solver.SolverTestScenes;

namespace Fulcrum.Tests.Solver
{
    /// <summary>
    /// Restitution where several contacts close within one step: a Newton's cradle whose gaps
    /// the first ball crosses in less than a step. Restitution 1 may lose energy where impacts
    /// cannot be separated in time, but it must never add any.
    /// </summary>
    public class RestitutionChainTests
    {
        const float Dt = 1f / 60f;
        const float G = 9.81f;
        const float Rod = 1.5f, Radius = 0.1f;

        static (World w, BodyHandle[] balls) Cradle(SolverType solver, float gap, int count, int iterations, int substeps)
        {
            WorldSettings s = Settings(solver);
            s.Iterations = iterations;
            s.Substeps = substeps;
            var w = new World(s);
            float spacing = 2 * Radius + gap;
            var balls = new BodyHandle[count];
            for (int i = 0; i < count; i++)
            {
                var anchor = new Vector3((i - (count - 1) / 2f) * spacing, 2, 0);
                // The first ball is released from 30 degrees.
                Vector3 at = i == 0 ? anchor + Rod * new Vector3(-MathF.Sin(MathF.PI / 6), -MathF.Cos(MathF.PI / 6), 0) : anchor - new Vector3(0, Rod, 0);
                balls[i] = Sphere(w, at, Radius, 32.7f, friction: 0, restitution: 1);
                w.CreateJoint(JointDef.Distance(BodyHandle.None, balls[i], anchor, Vector3.Zero, Rod, Rod));
            }
            return (w, balls);
        }

        static float Energy(World w, BodyHandle[] balls)
        {
            float e = 0;
            foreach (BodyHandle b in balls)
            {
                var body = w.GetBody(b);
                e += body.KineticEnergy + body.Mass * G * body.CenterOfMass.Y;
            }
            return e;
        }

        // The release energy above the lowest point, J: what an error is compared with.
        static float SwingEnergy(World w, BodyHandle[] balls) => w.GetBody(balls[0]).Mass * G * Rod * (1 - MathF.Cos(MathF.PI / 6));

        [TestCase(SolverType.Tgs, 0.01f, 5, 4, 4)]
        [TestCase(SolverType.Tgs, 0.005f, 5, 4, 4)]
        [TestCase(SolverType.Tgs, 0.01f, 5, 8, 2)]
        [TestCase(SolverType.Tgs, 0.01f, 5, 4, 1)]
        [TestCase(SolverType.Tgs, 0.002f, 3, 4, 4)]
        [TestCase(SolverType.Pgs, 0.01f, 5, 4, 1)]
        [TestCase(SolverType.Pgs, 0.005f, 5, 10, 1)]
        [TestCase(SolverType.Pgs, 0.01f, 3, 4, 1)]
        public void Cradle_with_gaps_crossed_within_one_step_never_gains_energy(SolverType solver, float gap, int count, int iterations, int substeps)
        {
            (World w, BodyHandle[] balls) = Cradle(solver, gap, count, iterations, substeps);
            float e0 = Energy(w, balls), swing = SwingEnergy(w, balls), worst = 0;
            for (int n = 0; n < 90; n++)
            {
                w.Step(Dt);
                worst = MathF.Max(worst, Energy(w, balls) - e0);
            }
            TestContext.Out.WriteLine($"{solver} {iterations}x{substeps}, {count} balls, gap {gap * 1000:F0} mm: largest energy gain {worst / swing * 100:F2} % of the swing energy");
            Assert.That(worst, Is.LessThan(0.01f * swing));
        }

        // A substep moves the released ball 0.83 cm: with 1 cm gaps TGS sees each impact in a
        // substep of its own and exchanges the velocities pair by pair.
        [Test]
        public void Tgs_cradle_with_1cm_gaps_hands_the_whole_velocity_to_the_last_ball()
        {
            (World w, BodyHandle[] balls) = Cradle(SolverType.Tgs, 0.01f, 5, 4, 4);
            float v0 = MathF.Sqrt(2 * G * Rod * (1 - MathF.Cos(MathF.PI / 6)));
            float lastSpeed = 0;
            for (int n = 0; n < 50; n++)
            {
                w.Step(Dt);
                lastSpeed = MathF.Max(lastSpeed, w.GetBody(balls[4]).LinearVelocity.Length());
            }
            float firstSpeed = w.GetBody(balls[0]).LinearVelocity.Length();
            TestContext.Out.WriteLine($"release speed {v0:F3} m/s; last ball's top speed {lastSpeed:F3} m/s; first ball afterwards {firstSpeed:F3} m/s");
            Assert.That(lastSpeed, Is.EqualTo(v0).Within(0.03f * v0));
            Assert.That(firstSpeed, Is.LessThan(0.05f * v0));
        }
    }
}
