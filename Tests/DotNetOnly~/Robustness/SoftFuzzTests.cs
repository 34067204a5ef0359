using System.Collections.Generic;
using Fulcrum.Runner;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.Robustness
{
    /// <summary>
    /// Seeded hostile soft-body worlds (SoftFuzz: every mesh kind, both material models, E 1e3
    /// to 1e10 Pa, nu up to 0.4999, both soft solvers, pins to the world and to rigid bodies,
    /// rigid bodies of 0.01 kg to 10 t dropped or thrown onto them). Each world must be refused
    /// by the API with an ArgumentException, or run without a body escaping further than its
    /// speeds allow; divergence (a NaN, or a tet passing tenfold its volume and more than
    /// doubling it in a step) must be
    /// reported, never hidden. The worlds that still diverge, gain mechanical energy or end
    /// with an inverted element are counted and the counts held as ceilings, so they can only
    /// go down; each failing world is listed one per line so it can be replayed
    /// (<c>fulcrum fuzz --soft --count 1 --seed N</c>).
    /// <para>
    /// Known and not yet fixed (seeds 0-199): 1 world diverges (reported), none gains energy, 2
    /// end with an inverted element (53 and 73, since XPBD vertices keep their predicted
    /// velocity; 0 before); seeds 200-399: 1, 1 and 0; seeds 400-599: 0, 1 and 2 (482 newly, 560
    /// where it diverged; 0-599 measured again then); seeds 600-799: 1, 1 and 1; seeds 800-999:
    /// 0, 1 and 1 (600-999 as last measured before that change; 13 worlds; 10 before it, 11
    /// before two Newton bodies on one rigid body saw each other's response, 14 before a step
    /// that blows a body apart was taken again with finer substeps; Documentation~/SoftSolvers.md
    /// keeps the history). Before the Newton solver took
    /// attached rigid bodies into its step, its energy guard counted the rigid bodies it moves
    /// and a pinned body's step started from the substep's start, 19, 3 and 4, and 21, 2 and 1
    /// (before the guard, 29 diverged of 0-199).
    /// </para>
    /// </summary>
    public class SoftFuzzTests
    {
        // Measured with the fixes of the soft fuzz (attachment hand-over, attachment inertia
        // scaling, attached vertices out of the contacts, bounded Newton factorisation, the
        // Newton energy guard, attached bodies in the Newton step) on seeds 0-99, 180 steps each. Before them the same seeds hung (seed 3: a Newton
        // factorisation retrying forever on a NaN matrix) or turned rigid bodies to NaN within
        // a step (7, 9, 24: cloths and beams pinned to light or spinning bodies).
        // Raised with the Newton damping and guard that leave a body's rigid motion alone (a free
        // spinning Newton body kept 25 % of its angular momentum in 2 s; a Newton body resting on
        // another soft body was thrown off): seeds 47 and 93 (diverged) and 53 and 94 (ended
        // inverted), heavy bodies crushing very soft Newton bodies (E 2e3-3e4 Pa), fail since;
        // over seeds 0-599 the failing worlds went from 28 to 32 (33 before this session's fixes).
        // Lowered with soft-soft contact inside the Newton step (a Newton body's step sees the
        // other soft body's inertia; corrections after it reach a Newton body as velocity only):
        // seeds 53 (ended inverted) and 86 (diverged), a Newton body on another soft body, pass;
        // over seeds 0-599 the failing worlds went from 32 to 26.
        // Then Newton bodies got friction with the ground (they had none): over seeds 0-599 the
        // failing worlds went from 26 to 24, but seed 21 (a very soft Newton sphere pinned to a
        // body) ends inverted, seed 94 (another) diverges where it ended inverted, and seed 77 (a
        // Newton box attached to an 11 kg body that a 2.2 t body strikes) gains energy; seed 93
        // passes: raised 1/0/0 -> 1/0/1 and 3/0/1 -> 3/1/0.
        // Then a Newton body's friction reached the vertices its springs hold at the collision
        // radius and went patch by patch (a resting patch held as one, a sliding one braking
        // with the cone of all its vertices; kinetic friction had been 5-27 % weak and a resting
        // cube crept): seeds 21 and 77 pass, 94 ends inverted where it diverged: 1/0/1 -> 1/0/0
        // and 3/1/0 -> 2/0/1 (over seeds 0-599 the failing worlds went from 24 to 23).
        // Then a Newton step whose exact system is not positive definite is assembled again with
        // each element's tangent filtered by its eigenvalues' absolute values (DefiniteTangent)
        // instead of the whole matrix shifted to the edge of definiteness: seeds 271, 323, 409 and
        // 478 (nearly incompressible Newton bodies pinned to bodies or on other soft bodies)
        // pass; 42 (a nu 0.4999 sphere dragged across the ground on a 3 m lever by a body that
        // then strikes the ground) and 354 (a 72 kg stiff Newton box on a 2.4 kg nu 0.4999 one)
        // fail again; 94 ends inverted: 1/0/0 -> 2/0/0 (over seeds 0-599 the failing worlds went
        // from 23 to 21).
        // Then a body's attachments were projected as one block (a light body swung about its
        // lever by each attachment in turn gained energy from nothing): 102, 161, 243, 330 and 403
        // pass, none fails newly; the ceilings here do not move (over seeds 0-599 21 -> 16).
        // Then the classic energy's XPBD projection got a trust region (no vertex moved more than
        // half a tet's size by one projection; a stiff classic box landing on an edge was crushed
        // and then thrown to NaN by metre-long corrections) and a body counts as blown apart only
        // where a tet passes tenfold its volume growing more than twice in the step (a very soft
        // body squeezed out from under a heavy one passed tenfold slowly and came back): 73, 124,
        // 187, 235, 338, 536, 639, 687, 950, 959 and 991 pass, none fails newly: 2/0/1 -> 1/0/1
        // (over seeds 0-999 the failing worlds went from 27 to 16).
        // Then a Newton step that took a vertex into a shape was followed by one more step holding
        // it with its overlap spring (the contact pass had pushed it out alone): 237, 649 and 681
        // pass, 168 gains 15.3 J against 13.6 J allowed; the ceilings do not move (over seeds
        // 0-999 16 -> 14).
        // Then the tets that hold a pinned vertex were left out of the blow-up rule (a very soft
        // box pinned at one corner and knocked to the ground stretched the tet at the pin to 400
        // times its volume and back): 47 passes, none fails newly: 2/0/0 -> 1/0/0 (over seeds
        // 0-999 14 -> 13).
        // Then the tets next to an inverted one were held at J >= 0.02 instead of left free (a
        // sphere pinned under a heavy body had its inversion spread tet by tet): 94 and 246 pass,
        // 959 diverges newly: 1/0/0 and 1/0/1 -> 1/0/0 and 1/0/0 (over seeds 0-999 13 -> 12).
        // Then a Newton body on one flat contact was turned back about its normal after each
        // step (KeepContactSpin) and its ground springs' support taken from the step's solve
        // instead of the float positions: 649 and 740 pass; 545 (a nu 0.4999 Newton beam among
        // four bodies), 681 and 992 (stiff or very soft nu 0.4999 Newton bodies pinned to bodies
        // that strike the ground) fail newly, on paths that part from the old ones long before
        // (992: a body at y 0.18 m at step 120 that was at 3.74 m) and end in the strike of a
        // nearly incompressible pinned body already written down for 740; the ceilings here do
        // not move (over seeds 0-999 12 -> 13).
        // Then a Newton body's friction waited for its last iteration's step, a later step's
        // support replaced the earlier ones, and the shares of a sliding patch of a free body
        // were held to the patch's cone: the ceilings here do not move. (The same cap for pinned
        // and attached bodies made 53 end inverted and 77 and 229 diverge, and replacing the
        // support within the first iteration made 47 diverge; neither landed.)
        // Then a step in which a soft body blew apart was taken again from its start with 16 times
        // the substeps (SoftBodySystem.Step): 42 (a nu 0.4999 Newton sphere pinned 3 m from a
        // body that strikes the ground and spins up to 83 rad/s), 681 and 959 pass; 784 gains
        // energy where it diverged; none fails newly: 1/0/0 -> 0/0/0 (over seeds 0-999 14 -> 11,
        // both builds run side by side on a lent 16-core machine).
        // Then two soft bodies attached to one rigid body saw each other: a Newton step counts the
        // other Newton bodies' condensed response and hands them the move it stands for, an XPBD
        // attachment projection moves the other bodies' attached vertices with the rigid body (a
        // 20 g hub holding a sphere and a box was dragged by each in turn;
        // ImplicitNewtonSolver.SharedBodies, AttachmentSolver.SharedVertices): 82 passes:
        // 1/0/0 -> 0/0/0. Only worlds with two soft bodies on one rigid body are touched (of the
        // 44 in seeds 0-29999, 15 failed and 6 fail now).
        // Then XPBD vertices no constraint moves kept their predicted velocity (free fall far from
        // the origin, SoftBody.EndPositions): every trajectory moves at rounding level, and two
        // worlds now end with an inverted element: 73 (a 0.16 kg box pinned to a body: its tets
        // at the pins reach J -11 at step 40 and -0.35 at step 160 with the build before too,
        // which happened to end at +0.27 at step 179) and 53 (a 1.4 t Newton box at E 2.8e4 Pa
        // pinned to the world among heavy bodies: least J 0.19 with the build before; the runs
        // part ways and a later crush inverts it, -0.40 at step 155); 959 no longer needs its
        // step taken again: 0/0/0 -> 0/0/2 here.
        // Then pinned bodies took the volume floor (53's Newton box hangs from its pin, too soft
        // for its weight: VolumeFloor) and anchors of XPBD bodies driven into the ground pushed
        // their bodies out (73's box, dragged 0.33 m into the ground by its pins:
        // ShapeContactSolver.AnchorsOut): both pass, none fails newly: 0/0/2 -> 0/0/0.
        [TestCase(0, 50, 0, 0, 0)]
        [TestCase(50, 50, 0, 0, 0)]
        public void Hostile_soft_worlds_are_refused_or_never_escape(int firstSeed, int count, int divergedMeasured, int energyGainsMeasured, int invertedMeasured)
        {
            var failures = new List<string>();
            var escapes = new List<string>();
            var gains = new List<string>();
            var inverted = new List<string>();
            int refused = 0;
            for (int seed = firstSeed; seed < firstSeed + count; seed++)
            {
                SoftFuzz.Outcome o = SoftFuzz.Run(seed, 180);
                if (o.Refused) refused++;
                if (o.Failure != null) failures.Add(o.Failure);
                else if (o.Escape != null) escapes.Add(o.Escape);
                else if (o.EnergyGain != null) gains.Add(o.EnergyGain);
                else if (o.Inverted != null) inverted.Add(o.Inverted);
            }
            TestContext.Out.WriteLine($"{count} soft worlds: {refused} refused, {failures.Count} diverged (reported), {escapes.Count} escaped, {gains.Count} gained energy, {inverted.Count} ended inverted");
            foreach (string f in failures) TestContext.Out.WriteLine("diverged: " + f);
            foreach (string e in escapes) TestContext.Out.WriteLine("escaped: " + e);
            foreach (string g in gains) TestContext.Out.WriteLine("energy: " + g);
            foreach (string i in inverted) TestContext.Out.WriteLine("inverted: " + i);
            Assert.That(escapes, Is.Empty);
            Assert.That(failures.Count, Is.LessThanOrEqualTo(divergedMeasured));
            Assert.That(gains.Count, Is.LessThanOrEqualTo(energyGainsMeasured));
            Assert.That(inverted.Count, Is.LessThanOrEqualTo(invertedMeasured));
        }

        // Soft fuzz seed 42: a 12.5 kg body thrown at 24 m/s drags a Newton sphere (0.7 kg,
        // nu 0.4999) pinned 3 m from its centre along the ground. At step 30 the body strikes
        // the ground and the rigid solve spins it up to 83 rad/s; the sphere's step diverges and
        // the sphere is put back where the step began. The body was left with what the failing
        // step had pushed onto it, 154 m/s, 14 cm into the ground, and fell on through it. Now
        // every rigid body the soft bodies moved in that step is put back as the rigid solve
        // left it, before the Diverged event is raised.
        [Test]
        public void A_body_whose_pinned_soft_body_diverges_keeps_what_the_rigid_solve_gave_it()
        {
            World w = SoftFuzz.Build(42, out BodyHandle[] rigid, out SoftBodyHandle[] soft, out _, out _)!;
            SoftBodySystem system = SoftBodySystem.Of(w)!;
            system.RetrySubstepFactor = 1; // taken again with finer substeps, the step no longer diverges
            float speedInEvent = -1;
            system.Diverged += (handle, step) => speedInEvent = w.GetBody(rigid[0]).LinearVelocity.Length();
            float before = 0;
            int step = 0;
            for (; step < 180 && system.DivergenceCount == 0; step++)
            {
                before = w.GetBody(rigid[0]).LinearVelocity.Length();
                w.Step(1 / 60f);
            }
            BodyRef body = w.GetBody(rigid[0]);
            TestContext.Out.WriteLine($"diverged at step {step - 1}: body at {before:F2} m/s before the step, {body.LinearVelocity.Length():F2} m/s and y {body.Position.Y:F3} m after it ({body.AngularVelocity.Length():F1} rad/s)");
            Assert.That(system.DivergenceCount, Is.EqualTo(1), "the world still diverges there (the case this test holds)");
            Assert.That(body.LinearVelocity.Length(), Is.LessThan(before + 1f), "no speed from the failing soft step");
            Assert.That(body.Position.Y, Is.GreaterThan(0f), "not pushed into the ground");
            Assert.That(speedInEvent, Is.EqualTo(body.LinearVelocity.Length()), "the event sees the world as it is left");
        }

        // Worlds in which a soft body blew apart at the default substeps, and that finer substeps
        // carry through: the step is taken again (SoftBodySystem.RetriedSteps) and the world runs
        // clean; with no step taken again (RetrySubstepFactor 1) the same world diverges. 681: a
        // 3 kg nu 0.4999 Newton box pinned to a body that strikes the ground; 42: a 0.7 kg
        // nu 0.4999 Newton sphere pinned 3 m from a 12.5 kg body that strikes the ground and
        // spins up. (959, a nu 0.4999 sphere landing on a very soft beam pinned to the world, was
        // the second case until free vertices kept their predicted velocity exactly: it runs
        // clean at the default substeps since, and is replayed below.)
        [TestCase(42)]
        [TestCase(681)]
        public void A_soft_world_that_blows_apart_at_the_default_substeps_is_taken_again_and_runs_clean(int seed)
        {
            SoftFuzz.Outcome o = SoftFuzz.Run(seed, 180);
            TestContext.Out.WriteLine($"seed {seed}: {o.Retried} step(s) taken again, energy rise {o.MaxEnergyRise:G3} J of {o.EnergyAllowance:G3} J allowed, end min J {o.EndMinJ:F3}");
            Assert.That(o.Retried, Is.GreaterThanOrEqualTo(1));
            Assert.That(o.Failure ?? o.Escape ?? o.EnergyGain ?? o.Inverted, Is.Null);

            World w = SoftFuzz.Build(seed, out _, out _, out _, out _)!;
            SoftBodySystem system = SoftBodySystem.Of(w)!;
            system.RetrySubstepFactor = 1;
            for (int n = 0; n < 180 && system.DivergenceCount == 0; n++) w.Step(1f / 60f);
            Assert.That(system.DivergenceCount, Is.GreaterThan(0), "without the second try the world diverges (the case this test holds)");
        }

        // The worlds that showed each mechanism, replayed: 7 (a 33 g body thrown at 28 m/s with
        // a cloth pinned 5 m from its centre: the damping hand-over overshot and the body was
        // NaN in step 0), 9 (a 533 kg body spinning at 16 rad/s with a 1 kg cloth pinned to it:
        // the soft inertia scaled for the attached body made the cloth float and gave the body
        // 1e8 J in two steps), 14 (a capsule at E 1e10 Pa pinned to a body, thrown: NaN in step 0),
        // 229 (a 0.16 kg Newton box at E 2.7e9 Pa pinned 9 m from the centre of a 3.8 t body
        // spinning at 17 rad/s: projected onto their anchors after each Newton step, the attached
        // vertices strained the box until it inverted in step 0; then its inertia, scaled for a
        // 778 kg box it swept past, doubled the big body's speed), 358 (a 239 kg body dropped on
        // a 1.4 kg nu = 0.4999 Newton jelly: the energy guard stood aside while a rigid body
        // touched it, and it blew apart at step 53), 639 (a 37 kg classic Neo-Hookean box at
        // E 4.5e8 Pa landing on an edge: the projections of its crushed tets moved vertices metres
        // and it went to NaN), 991 (a 2.9 kg sphere at E 1.9e3 Pa under a 1 t body, squeezed out
        // past tenfold volume a few percent a step and back: reported as blown apart and frozen),
        // 237 (a 3.9e8 Pa Newton box on a soft Newton box: the contact pass pushed the vertices its
        // Newton step took into the ground out alone, and a tet ended at J -0.49), 47 (a 122 kg
        // Newton box at E 7.7e3 Pa pinned at one corner, knocked to the ground by a 343 kg body:
        // the tet at the pin went from 5 to 98 times its volume in a step and 400 in six, and
        // back, and was reported as blown apart and frozen), 94 (a 28 kg Newton sphere at
        // E 2.3e3 Pa pinned to a 2.9 t body that lands on it on a slope: one tet inverted, its
        // neighbours were left without a floor, and the inversion spread to 58 of 120 tets), 82 (a
        // 20 g body holding a Newton sphere and a Newton box by pins: once the sphere landed, the
        // two steps dragged the body in turn and the sphere, crushed by it, inverted and blew apart).
        [TestCase(47)]
        [TestCase(82)]
        [TestCase(94)]
        [TestCase(237)]
        [TestCase(639)]
        [TestCase(991)]
        [TestCase(7)]
        [TestCase(9)]
        [TestCase(14)]
        [TestCase(229)]
        [TestCase(358)]
        [TestCase(959)]
        public void A_soft_world_that_once_blew_up_runs_clean(int seed)
        {
            SoftFuzz.Outcome o = SoftFuzz.Run(seed, 180);
            TestContext.Out.WriteLine($"seed {seed}: energy rise {o.MaxEnergyRise:G3} J of {o.EnergyAllowance:G3} J allowed, end min J {o.EndMinJ:F3}");
            Assert.That(o.Refused, Is.False);
            Assert.That(o.Failure, Is.Null);
            Assert.That(o.Escape, Is.Null);
            Assert.That(o.EnergyGain, Is.Null);
            Assert.That(o.Inverted, Is.Null);
        }
    }
}
