using System.Numerics;
using Fulcrum.Collision;
using NUnit.Framework;

namespace Fulcrum.Tests.Solver
{
    /// <summary>
    /// The impulse events report is the one the solver applied: over a landing it must equal
    /// the ball's momentum change plus gravity's impulse (the only other force).
    /// </summary>
    public class AppliedImpulseTests
    {
        [TestCase(SolverType.Tgs, 4)]
        [TestCase(SolverType.Tgs, 1)]
        [TestCase(SolverType.Pgs, 1)]
        public void Reported_impulse_of_a_landing_equals_the_momentum_change(SolverType solver, int substeps)
        {
            WorldSettings settings = WorldSettings.Default;
            settings.Solver = solver;
            settings.Substeps = substeps;
            settings.EnableSleeping = false;
            var world = new World(settings);
            BodyHandle ground = world.CreateBody(BodyDef.Static(new Vector3(0, -0.5f, 0)));
            world.AddShape(ground, ShapeDef.Of(ShapeGeometry.Box(new Vector3(5, 0.5f, 5))));
            BodyDef def = BodyDef.Dynamic(new Vector3(0, 1.5f, 0));
            def.Mass = 1f;
            BodyHandle ball = world.CreateBody(def);
            world.AddShape(ball, ShapeDef.Of(ShapeGeometry.Sphere(0.5f)));

            const float dt = 1f / 60f;
            float reported = 0;
            float vBefore = 0;
            int touchingSteps = 0;
            for (int n = 0; n < 120; n++)
            {
                float v0 = world.GetBody(ball).LinearVelocity.Y;
                world.Step(dt);
                float stepImpulse = 0;
                foreach (ContactEvent e in world.ContactEvents)
                    if (e.Kind != ContactEventKind.End) stepImpulse += e.NormalImpulse;
                if (stepImpulse > 0 && touchingSteps == 0) vBefore = v0;
                if (stepImpulse > 0) touchingSteps++;
                reported += stepImpulse;
            }
            Assert.That(touchingSteps, Is.GreaterThan(0));
            float vAfter = world.GetBody(ball).LinearVelocity.Y;
            // Momentum balance over the touching steps: J - m g t = m (v_end - v_start).
            float expected = 1f * (vAfter - vBefore) + 1f * 9.81f * touchingSteps * dt;
            Assert.That(reported, Is.EqualTo(expected).Within(0.03f * expected));
        }
    }
}
