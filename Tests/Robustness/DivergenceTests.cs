using System;
using System.Linq;
using System.IO;
using System.Numerics;
using Fulcrum.SoftBodies;
using NUnit.Framework;
using static Fulcrum.Tests.Solver.SolverTestScenes;

namespace Fulcrum.Tests.Robustness
{
    /// <summary>
    /// Divergence is reported, never hidden (issue 11): a body whose state turns non-finite or
    /// leaves the world bounds is put back at its pose from the start of the step, stopped, and
    /// reported with its handle, step and kind; the runner exits 3 with one line.
    /// </summary>
    public partial class DivergenceTests
    {
        [Test]
        public void A_body_turned_non_finite_is_stopped_at_its_last_pose_and_reported()
        {
            var w = new World();
            Ground(w);
            BodyHandle box = Box(w, new Vector3(0, 0.5f, 0), new Vector3(0.5f), 1f);
            BodyHandle top = Box(w, new Vector3(0, 1.5f, 0), new Vector3(0.5f), 1f);
            for (int n = 0; n < 30; n++) w.Step(1 / 60f);
            Vector3 before = w.GetBody(box).Position;
            Divergence? seen = null;
            w.Diverged += d => seen = d;
            // What a solver bug would do: a NaN in the body's state (no public call can write one).
            w.Bodies.LinearVelocity[box.Index] = new Vector3(float.NaN, 0, 0);
            w.GetBody(box).WakeUp();
            long step = w.StepIndex;
            w.Step(1 / 60f);
            Assert.That(seen.HasValue, "Diverged was raised");
            Assert.That(seen!.Value.Body, Is.EqualTo(box));
            Assert.That(seen.Value.Kind, Is.EqualTo(DivergenceKind.NonFinite));
            Assert.That(seen.Value.Step, Is.EqualTo(step));
            Assert.That(w.DivergenceCount, Is.EqualTo(1));
            Assert.That(w.LastDivergence.Body, Is.EqualTo(box));
            for (int n = 0; n < 60; n++) w.Step(1 / 60f);
            foreach (BodyHandle b in new[] { box, top })
            {
                BodyRef r = w.GetBody(b);
                Assert.That(float.IsFinite(r.Position.X + r.Position.Y + r.Position.Z + r.LinearVelocity.Length() + r.AngularVelocity.Length()), $"{b} stays finite");
            }
            Assert.That(Vector3.Distance(w.GetBody(box).Position, before), Is.LessThan(0.01f), "back at its pose and at rest");
            Assert.That(w.DivergenceCount, Is.EqualTo(1), "once stopped it does not diverge again");
        }

        [Test]
        public void A_body_leaving_the_world_bounds_is_reported_once_and_stopped_inside()
        {
            WorldSettings s = WorldSettings.Default;
            s.Gravity = Vector3.Zero;
            var w = new World(s);
            BodyHandle b = Sphere(w, new Vector3(Limits.MaxPosition - 10, 0, 0), 0.5f, 1f);
            BodyRef r = w.GetBody(b);
            r.LinearVelocity = new Vector3(400, 0, 0);
            int count = 0;
            w.Diverged += d => count++;
            for (int n = 0; n < 60; n++) w.Step(1 / 60f);
            Assert.That(count, Is.EqualTo(1));
            Assert.That(w.LastDivergence.Kind, Is.EqualTo(DivergenceKind.OutOfBounds));
            Assert.That(w.GetBody(b).Position.X, Is.LessThanOrEqualTo(Limits.MaxPosition));
            Assert.That(w.GetBody(b).LinearVelocity, Is.EqualTo(Vector3.Zero));
        }

        [Test]
        public void A_soft_body_turned_non_finite_is_put_back_at_rest_and_reported()
        {
            (World w, SoftBodyHandle jelly) = JellyOnGround();
            SoftBodySystem system = SoftBodySystem.Of(w)!;
            SoftBody body = w.GetSoftBody(jelly);
            long reportedStep = -1;
            system.Diverged += (h, step) => reportedStep = step;
            long stepIndex = w.StepIndex;
            body.V[3] = new Vector3(float.NaN, 0, 0); // what a solver bug would do
            w.Step(1 / 60f);
            Assert.That(system.DivergenceCount, Is.EqualTo(1));
            Assert.That(system.LastDiverged, Is.EqualTo(jelly));
            Assert.That(reportedStep, Is.EqualTo(stepIndex));
            for (int n = 0; n < 30; n++) w.Step(1 / 60f);
            foreach (Vector3 x in body.X) Assert.That(float.IsFinite(x.X + x.Y + x.Z));
            Assert.That(system.DivergenceCount, Is.EqualTo(1));
        }

        [Test]
        public void A_soft_body_blown_apart_within_the_bounds_is_put_back_and_reported()
        {
            (World w, SoftBodyHandle jelly) = JellyOnGround();
            SoftBodySystem system = SoftBodySystem.Of(w)!;
            system.RetrySubstepFactor = 1; // the put-back itself: no step taken again (see the retry tests below)
            SoftBody body = w.GetSoftBody(jelly);
            var start = body.X.ToArray();
            body.V[3] = new Vector3(0, 3000, 0); // finite, and 50 m in one step: what an exploding solve does
            w.Step(1 / 60f);
            var j = new float[body.ElementCount];
            body.ComputeElementJ(j);
            Assert.That(system.DivergenceCount, Is.EqualTo(1));
            Assert.That(body.X, Is.EqualTo(start), "back at the step's start");
            foreach (float x in j) Assert.That(MathF.Abs(x), Is.LessThanOrEqualTo(SoftBody.MaxVolumeRatio));
            for (int n = 0; n < 30; n++) w.Step(1 / 60f);
            Assert.That(system.DivergenceCount, Is.EqualTo(1));
        }

        // The same with the jelly pinned at a top corner: the tets that hold the pinned vertex do
        // not count for the blow-up rule (a pin stretches them without bound when the body is
        // carried away from it), and a blow-up among the free tets is still caught.
        [Test]
        public void A_pinned_soft_body_blown_apart_within_the_bounds_is_put_back_and_reported()
        {
            var w = new World();
            Ground(w);
            var def = SoftBodyDef.Of(SoftMesh.Box(new Vector3(0.5f), 2, 2, 2), MaterialPresets.Jelly, new Vector3(0, 0.3f, 0));
            def.Pins = new[] { SoftPin.ToWorld(new Vector3(-0.26f, 0.24f, -0.26f), new Vector3(-0.24f, 0.26f, -0.24f)) };
            SoftBodyHandle jelly = w.CreateSoftBody(def);
            for (int n = 0; n < 20; n++) w.Step(1 / 60f);
            SoftBodySystem system = SoftBodySystem.Of(w)!;
            system.RetrySubstepFactor = 1;
            SoftBody body = w.GetSoftBody(jelly);
            Assert.That(body.W.Count(x => x == 0f), Is.EqualTo(1), "one vertex pinned");
            // The vertex farthest from the pin, flung: what an exploding solve does.
            int far = 0;
            for (int i = 1; i < body.VertexCount; i++)
                if (body.X[i].X + body.X[i].Z - body.X[i].Y > body.X[far].X + body.X[far].Z - body.X[far].Y) far = i;
            var start = body.X.ToArray();
            body.V[far] = new Vector3(0, 3000, 0);
            w.Step(1 / 60f);
            Assert.That(system.DivergenceCount, Is.EqualTo(1));
            Assert.That(body.X, Is.EqualTo(start), "back at the step's start");
        }

        // A very soft block (E 1e3 Pa, nu 0) held at one end and drawn out at 1 m/s by a
        // kinematic body at the other: its tets pass tenfold their volume a few percent a step.
        // That is a stretch, not an explosion (which grows the volume ratio by orders of magnitude
        // a step): the body must keep stretching, not be put back at rest. Before the growth rule
        // (SoftBody.BlowUpGrowth) it was reported as blown apart and frozen once a tet passed 10.
        [Test]
        public void A_soft_body_drawn_out_past_tenfold_volume_slowly_is_not_reported_as_blown_apart()
        {
            var w = new World();
            w.Gravity = Vector3.Zero;
            BodyDef mover = BodyDef.Kinematic(new Vector3(0.1f, 0, 0));
            mover.LinearVelocity = new Vector3(1f, 0, 0);
            BodyHandle handle = w.CreateBody(mover);
            var def = SoftBodyDef.Of(SoftMesh.Box(new Vector3(0.2f, 0.1f, 0.1f), 2, 1, 1), new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e3f, 0f, 1000f), Vector3.Zero);
            def.Pins = new[] { SoftPin.ToWorld(new Vector3(-0.2f, -1, -1), new Vector3(-0.09f, 1, 1)), SoftPin.ToBody(new Vector3(0.09f, -1, -1), new Vector3(0.2f, 1, 1), handle) };
            SoftBodyHandle block = w.CreateSoftBody(def);
            SoftBody body = w.GetSoftBody(block);
            SoftBodySystem system = SoftBodySystem.Of(w)!;
            var j = new float[body.ElementCount];
            float largest = 0;
            for (int n = 0; n < 150; n++)
            {
                w.Step(1 / 60f);
                body.ComputeElementJ(j);
                foreach (float x in j) largest = MathF.Max(largest, MathF.Abs(x));
            }
            float reach = body.X.Max(x => x.X);
            TestContext.Out.WriteLine($"largest |J| {largest:F1}, far end at x = {reach:F2} m, handle at {w.GetBody(handle).Position.X:F2} m, divergences {system.DivergenceCount}");
            Assert.That(largest, Is.GreaterThan(SoftBody.MaxVolumeRatio), "the tets did pass tenfold");
            Assert.That(system.DivergenceCount, Is.Zero);
            Assert.That(reach, Is.GreaterThan(2f), "still held by the handle, 2.6 m out");
        }

        // A 0.5 m jelly cube settled on the ground for 20 steps.
        // A step that blows a soft body apart is taken again from its start with 16 times the
        // substeps (SoftBodySystem.Step). A kick of 600 m/s to one vertex: at the default
        // substeps it runs 1 m a substep, four cells, and tears its tets open; at 16 times as
        // many (6 cm a substep) the tets hold it. The step taken again is the step a world set to
        // 16 times the substeps takes from the same start, bit for bit: positions, velocities,
        // contact memory and masses all go back before the second try. (The 3000 m/s kick above,
        // 31 cm a substep even then, leaves the retried step with a tet inverted to J -4.5.)
        [Test]
        public void A_soft_body_kicked_apart_is_taken_again_with_finer_substeps_and_stays_whole()
        {
            (World w, SoftBodyHandle jelly) = JellyOnGround();
            SoftBodySystem system = SoftBodySystem.Of(w)!;
            SoftBody body = w.GetSoftBody(jelly);
            body.V[3] = new Vector3(0, 600, 0);
            w.Step(1 / 60f);
            Assert.That(system.RetriedSteps, Is.EqualTo(1));
            Assert.That(system.DivergenceCount, Is.EqualTo(0));
            var j = new float[body.ElementCount];
            body.ComputeElementJ(j);
            foreach (float x in j) Assert.That(x, Is.GreaterThan(0f).And.LessThanOrEqualTo(SoftBody.MaxVolumeRatio));

            (World reference, SoftBodyHandle same) = JellyOnGround();
            SoftBody fine = reference.GetSoftBody(same);
            fine.V[3] = new Vector3(0, 600, 0);
            fine.Substeps = 16 * fine.SubstepsFor(1 / 60f);
            reference.Step(1 / 60f);
            Assert.That(SoftBodySystem.Of(reference)!.RetriedSteps, Is.EqualTo(0));
            Assert.That(body.X, Is.EqualTo(fine.X), "positions: the step at 16 times the substeps");
            Assert.That(body.V, Is.EqualTo(fine.V), "velocities");
        }

        // A body that blows apart again from where it was put back is not taken again step after
        // step (each try costs 16 steps' substeps): only the first step of a run of divergent
        // steps is retried, and after a clean step the next blow-up is retried again.
        [Test]
        public void A_soft_body_that_keeps_diverging_is_not_taken_again_step_after_step()
        {
            (World w, SoftBodyHandle jelly) = JellyOnGround();
            SoftBodySystem system = SoftBodySystem.Of(w)!;
            SoftBody body = w.GetSoftBody(jelly);
            for (int n = 0; n < 3; n++)
            {
                body.V[3] = new Vector3(float.NaN, 0, 0);
                w.Step(1 / 60f);
            }
            Assert.That(system.DivergenceCount, Is.EqualTo(3));
            Assert.That(system.RetriedSteps, Is.EqualTo(1));
            w.Step(1 / 60f);
            body.V[3] = new Vector3(float.NaN, 0, 0);
            w.Step(1 / 60f);
            Assert.That(system.DivergenceCount, Is.EqualTo(4));
            Assert.That(system.RetriedSteps, Is.EqualTo(2));
        }

        // A step taken again is part of the run a saved state continues: saved before it and
        // restored into a world built the same way, the retried step and the ones after it come
        // out bit for bit, and the count of steps taken again travels with the state.
        [Test]
        public void A_state_saved_before_a_retried_step_continues_bit_identically()
        {
            (World a, SoftBodyHandle jelly) = JellyOnGround();
            a.GetSoftBody(jelly).V[3] = new Vector3(0, 600, 0);
            byte[] state = State.StateRoundTripTests.Save(a);
            for (int n = 0; n < 10; n++) a.Step(1 / 60f);
            (World b, SoftBodyHandle again) = JellyOnGround();
            State.StateRoundTripTests.Restore(b, state);
            for (int n = 0; n < 10; n++) b.Step(1 / 60f);
            Assert.That(SoftBodySystem.Of(a)!.RetriedSteps, Is.EqualTo(1));
            Assert.That(SoftBodySystem.Of(b)!.RetriedSteps, Is.EqualTo(1));
            Assert.That(b.GetSoftBody(again).X, Is.EqualTo(a.GetSoftBody(jelly).X));
            Assert.That(b.GetSoftBody(again).V, Is.EqualTo(a.GetSoftBody(jelly).V));
        }

        [Test]
        public void A_retry_substep_factor_outside_1_to_64_is_refused()
        {
            (World w, _) = JellyOnGround();
            SoftBodySystem system = SoftBodySystem.Of(w)!;
            Assert.That(system.RetrySubstepFactor, Is.EqualTo(16));
            Assert.That(() => system.RetrySubstepFactor = 0, Throws.TypeOf<ArgumentOutOfRangeException>().With.Message.Contains("RetrySubstepFactor"));
            Assert.That(() => system.RetrySubstepFactor = 65, Throws.TypeOf<ArgumentOutOfRangeException>());
            Assert.That(system.RetrySubstepFactor, Is.EqualTo(16), "unchanged by a refused value");
            system.RetrySubstepFactor = 1;
            Assert.That(system.RetrySubstepFactor, Is.EqualTo(1));
        }

        static (World, SoftBodyHandle) JellyOnGround()
        {
            var w = new World();
            Ground(w);
            SoftBodyHandle jelly = w.CreateSoftBody(SoftBodyDef.Of(SoftMesh.Box(new Vector3(0.5f), 2, 2, 2), MaterialPresets.Jelly, new Vector3(0, 0.3f, 0)));
            for (int n = 0; n < 20; n++) w.Step(1 / 60f);
            return (w, jelly);
        }

        [Test]
        public void A_world_that_diverges_nothing_allocates_nothing_for_the_check()
        {
            var w = new World();
            Ground(w);
            for (int i = 0; i < 10; i++) Box(w, new Vector3(0, 0.5f + i, 0), new Vector3(0.5f), 1f);
            w.Diverged += d => Assert.Fail("nothing diverges");
            long bytes = Components.AllocationProbe.SteadyStateBytes(() => w.Step(1 / 60f));
            Assert.That(bytes, Is.EqualTo(0));
            Assert.That(w.DivergenceCount, Is.EqualTo(0));
        }
    }
}
