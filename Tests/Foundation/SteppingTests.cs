using System;
using System.Numerics;
using NUnit.Framework;

namespace Fulcrum.Tests.Foundation
{
    public class SteppingTests
    {
        [Test]
        public void Fixed_stepper_takes_whole_steps_and_carries_the_rest()
        {
            var stepper = new FixedStepper(1f / 60f, 8);
            int steps = 0;
            for (int frame = 0; frame < 144; frame++) steps += stepper.Consume(1f / 144f);
            // One second of frames is 60 steps, give or take the carried fraction.
            Assert.That(steps, Is.InRange(59, 60));
            Assert.That(stepper.Accumulator, Is.LessThan(stepper.FixedDt));
            Assert.That(stepper.InterpolationFactor, Is.InRange(0f, 1f));
        }

        [Test]
        public void Fixed_stepper_caps_steps_per_frame_and_drops_the_surplus()
        {
            var stepper = new FixedStepper(0.01f, 4);
            Assert.That(stepper.Consume(1f), Is.EqualTo(4));
            Assert.That(stepper.DroppedTime, Is.GreaterThan(0.9));
            Assert.That(stepper.Accumulator, Is.LessThan(0.01f));
        }

        [Test]
        public void Fixed_stepper_advances_the_world_by_whole_steps()
        {
            var world = new World();
            var stepper = new FixedStepper(1f / 120f);
            for (int frame = 0; frame < 60; frame++) stepper.Advance(world, 1f / 60f);
            Assert.That(world.StepIndex, Is.InRange(119, 120));
            Assert.That(world.Time, Is.EqualTo(world.StepIndex / 120.0).Within(1e-6));
        }

        [Test]
        public void Step_profile_reports_every_stage_and_the_total()
        {
            var world = new World();
            BodyHandle b = world.CreateBody(BodyDef.Dynamic(Vector3.Zero));
            world.AddShape(b, ShapeDef.Of(ShapeGeometry.Sphere(1)));
            world.Step(1f / 60f);
            StepProfile p = world.LastStepProfile;
            double sum = 0;
            foreach (StepStage s in Enum.GetValues(typeof(StepStage))) sum += p[s];
            Assert.That(p.Total, Is.GreaterThan(0));
            Assert.That(sum, Is.LessThanOrEqualTo(p.Total * 1.0001 + 1e-6));
        }

        [Test]
        public void Changing_the_world_from_inside_a_step_is_refused()
        {
            var world = new World();
            var probe = new MutatingStage();
            world.SoftBodyStage = probe;
            world.Step(1f / 60f);
            Assert.That(probe.Refusal, Is.InstanceOf<InvalidOperationException>());
            Assert.That(world.BodyCount, Is.EqualTo(0));
        }

        sealed class MutatingStage : ISoftBodyStage
        {
            public Exception? Refusal;
            public bool HasWork => true;
            public void Step(World world, float dt)
            {
                try { world.CreateBody(BodyDef.Default); }
                catch (Exception e) { Refusal = e; }
            }
        }
    }
}
