using System;
using System.Numerics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftBodies
{
    /// <summary>
    /// Coulomb friction between a Newton soft body and the ground, against the closed forms of a
    /// block pushed across a floor (it stops after v^2 / (2 mu g)) and of a block on a slope (it
    /// holds where tan(angle) &lt; mu, else slides at g (sin - mu cos)). The friction pass bounds
    /// a vertex's friction by mu times its normal impulse in the substep; a Newton body's
    /// vertices are held at the ground by springs inside its step, which left that pass no
    /// normal impulse: before the springs' impulse was counted, a Newton slab pushed at 1 m/s
    /// slid on at 0.99 m/s after 2 s, and a Newton cube on a 30 degree slope slid down as on
    /// ice whatever mu (7.36 m/s after 1.5 s at mu 0.8).
    /// </summary>
    public class NewtonFrictionTests
    {
        // A 0.3 m cube (3 cells, 1000 kg/m^3) set at rest on a plane tilted by degrees about z,
        // mu for both; the unit vector down the slope.
        static (World, SoftBody, Vector3) CubeOnSlope(float degrees, float mu, float youngs, float poisson, SoftSolver solver, int iterations = 0)
        {
            float angle = degrees * MathF.PI / 180f;
            var world = new World();
            var normal = new Vector3(-MathF.Sin(angle), MathF.Cos(angle), 0);
            BodyHandle ground = world.CreateBody(BodyDef.Static(Vector3.Zero));
            world.AddShape(ground, ShapeDef.Of(ShapeGeometry.Plane(normal, 0f)).With((ref ShapeDef s) => s.Friction = mu));
            var def = SoftBodyDef.Of(SoftMesh.Box(new Vector3(0.3f), 3, 3, 3), new NeoHookeanMaterial(MaterialModel.StableNeoHookean, youngs, poisson, 1000f), normal * 0.156f);
            def.Rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, angle);
            def.Solver = solver;
            if (iterations > 0) def.Iterations = iterations;
            def.Friction = mu;
            SoftBody cube = world.GetSoftBody(world.CreateSoftBody(def));
            return (world, cube, new Vector3(-MathF.Cos(angle), -MathF.Sin(angle), 0));
        }

        // The cube of CubeOnSlope run for two seconds: its stats after the first and the second.
        static (SoftBody, SoftBodyStats, SoftBodyStats, Vector3) TwoSecondsOnSlope(float degrees, float mu, float youngs, float poisson, SoftSolver solver, int iterations)
        {
            (World world, SoftBody cube, Vector3 down) = CubeOnSlope(degrees, mu, youngs, poisson, solver, iterations);
            SoftBodyScenes.Run(world, 60);
            SoftBodyStats half = cube.ComputeStats();
            SoftBodyScenes.Run(world, 60);
            return (cube, half, cube.ComputeStats(), down);
        }

        // A 1 x 0.2 x 1 m slab (6 x 2 x 6 cells) set on the ground at 1 m/s; mu is the mean of
        // the ground's 0.5 and the slab's 0.6. Measured: 0.093-0.094 m (Newton), 0.091-0.092 m
        // (XPBD) against 0.0927 m.
        [TestCase(SoftSolver.Newton, 1e5f, 0.3f)]
        [TestCase(SoftSolver.Newton, 1e7f, 0.49f)]
        [TestCase(SoftSolver.Xpbd, 1e6f, 0.3f)]
        public void A_slab_pushed_across_the_ground_stops_where_coulomb_friction_says(SoftSolver solver, float youngs, float poisson)
            => SlabStopsWhereCoulombSays(solver, youngs, poisson, 0f, 10f);

        // The slab of the tests above and below, pushed at 1 m/s on ground at height; how far it
        // slides against 1 / (2 mu g), mu 0.55, within tolerance percent, and stopped at 2 s.
        static void SlabStopsWhereCoulombSays(SoftSolver solver, float youngs, float poisson, float height, float tolerance)
        {
            World world = SoftBodyScenes.WorldWithGround(height, 0.5f);
            var def = SoftBodyDef.Of(SoftMesh.Box(new Vector3(1f, 0.2f, 1f), 6, 2, 6), new NeoHookeanMaterial(MaterialModel.StableNeoHookean, youngs, poisson, 1000f), new Vector3(0, height + 0.106f, 0));
            def.Solver = solver;
            def.LinearVelocity = new Vector3(1f, 0, 0);
            def.Friction = 0.6f;
            SoftBody slab = world.GetSoftBody(world.CreateSoftBody(def));
            float x0 = slab.ComputeStats().Centroid.X;
            SoftBodyScenes.Run(world, 120);
            SoftBodyStats s = slab.ComputeStats();
            float slid = s.Centroid.X - x0, mu = 0.55f, expected = 1f / (2f * mu * 9.81f);
            TestContext.Out.WriteLine($"{solver} E {youngs:E0} nu {poisson} on ground at {height} m: slid {slid:F4} m (closed form {expected:F4} m), speed at 2 s {s.Momentum.Length() / slab.TotalMass:F4} m/s");
            Assert.That(slid, Is.EqualTo(expected).Within(tolerance).Percent);
            Assert.That(s.Momentum.Length() / slab.TotalMass, Is.LessThan(0.01f), "stopped");
        }

        // The same slab on ground raised off the origin. A Newton vertex's share of the weight
        // sits a few nm into the ground's spring, below the float spacing of a coordinate at 10 m
        // (0.95 um); read back from the positions, the support was rounding and a slab on ground
        // at y = 10 m slid on at 0.75 m/s after 0.33 s (at y = 0 it had stopped at 0.2 s), at
        // 100 m at 0.95 m/s. It is now taken from the step's own solve. Measured since: Newton
        // 0.0925 / 0.0951 / 0.0824 m at 10 / 30 / 100 m, XPBD 0.0922 / 0.0917 / 0.0898 m,
        // against 0.0927 m. (Past 512 m a float cannot carry one substep's fall under gravity,
        // g h^2 = 27 um: an XPBD body at rest stayed in the air until vertices no constraint
        // moves kept their predicted velocity (DynamicsTests); Newton bodies and sliding there
        // are still quantised: CHANGELOG, Known limits.)
        [Test]
        public void A_slab_pushed_across_ground_away_from_the_origin_stops_where_coulomb_friction_says(
            [Values(SoftSolver.Newton, SoftSolver.Xpbd)] SoftSolver solver, [Values(10f, 30f, 100f)] float height)
            => SlabStopsWhereCoulombSays(solver, 1e7f, 0.49f, height, 15f);

        // A 0.3 m cube (3 cells) on a slope, mu for both the slope and the cube; the speed down
        // the slope 1.5 s after release against mu's closed form, and how far it moves in the
        // last second (at most creep, m/s, where it should hold). Measured (Newton):
        // - E 1e6 and 1e5 at 30 degrees, mu 0.8: crept 1.4 cm/s until friction reached the
        //   vertices the springs hold at the collision radius (ShapeContactSolver.FrictionSkin)
        //   and went patch by patch (HoldPatch); under 0.1 mm/s since;
        // - nu 0.49 at 30 degrees, mu 0.7, crept 13 cm/s, then 3.7 cm/s; E 1e8 at 20 degrees,
        //   mu 0.5, 31 cm/s, then 5.1 cm/s: friction after the step pulled back the touching
        //   vertices only, while the step had moved the whole body down the slope. A body at rest
        //   now sticks inside the Newton step (ImplicitNewtonSolver.Stick, capped at the patch's
        //   cone by ShapeContactSolver.CapSticks): both hold, 0.0 mm in the last second;
        // - mu 0.4 and 0.2 slide within 3 % of g (sin - mu cos) (XPBD: 1 % and 0 %).
        [TestCase(SoftSolver.Newton, 0.8f, 30f, 1e6f, 0.45f, 0.001f)]
        [TestCase(SoftSolver.Newton, 0.8f, 30f, 1e5f, 0.45f, 0.001f)]
        [TestCase(SoftSolver.Newton, 0.7f, 30f, 1e6f, 0.49f, 0.001f)]
        [TestCase(SoftSolver.Newton, 0.5f, 20f, 1e8f, 0.3f, 0.001f)]
        [TestCase(SoftSolver.Newton, 0.4f, 30f, 1e6f, 0.45f, 0f)]
        [TestCase(SoftSolver.Newton, 0.2f, 30f, 1e6f, 0.45f, 0f)]
        [TestCase(SoftSolver.Xpbd, 0.8f, 30f, 1e6f, 0.45f, 0.001f)]
        [TestCase(SoftSolver.Xpbd, 0.4f, 30f, 1e6f, 0.45f, 0f)]
        public void A_cube_on_a_slope_holds_or_slides_as_coulomb_friction_says(SoftSolver solver, float mu, float degrees, float youngs, float poisson, float creep)
        {
            float angle = degrees * MathF.PI / 180f;
            (World world, SoftBody cube, Vector3 down) = CubeOnSlope(degrees, mu, youngs, poisson, solver);
            SoftBodyScenes.Run(world, 30);
            Vector3 half = cube.ComputeStats().Centroid;
            SoftBodyScenes.Run(world, 60);
            SoftBodyStats end = cube.ComputeStats();
            float moved = Vector3.Dot(end.Centroid - half, down);
            float speed = Vector3.Dot(end.Momentum / cube.TotalMass, down);
            float expected = MathF.Max(0f, 9.81f * (MathF.Sin(angle) - mu * MathF.Cos(angle))) * 1.5f;
            TestContext.Out.WriteLine($"{solver} E {youngs:G} nu {poisson} at {degrees} degrees, mu {mu}: {speed:F3} m/s down the slope at 1.5 s (closed form {expected:F3}), moved {moved:F4} m in the last second");
            if (expected == 0f)
            {
                Assert.That(MathF.Abs(moved), Is.LessThan(creep), "holds (creeps less than the bound)");
                Assert.That(MathF.Abs(speed), Is.LessThan(Math.Max(0.005f, creep)));
            }
            else Assert.That(speed, Is.EqualTo(expected).Within(3).Percent, "slides at g (sin - mu cos)");
        }

        // The class of the two cases above: a cube resting on a slope with mu 15 % above
        // tan(angle) holds, whatever its stiffness and compressibility (E 1e5-1e9 Pa, nu
        // 0.3-0.4999) and either solver; measured over the second second (the softest settle in
        // the first, moving 18-36 mm). Before the Newton body stuck inside its step, 30 of the 40
        // Newton cases crept 1-90 mm in a second (the stiff and the nearly incompressible ones);
        // all hold now. XPBD held before and after (at most 0.26 mm).
        [Test]
        public void A_cube_resting_on_a_slope_holds_at_every_stiffness_and_poisson_ratio(
            [Values(SoftSolver.Newton, SoftSolver.Xpbd)] SoftSolver solver,
            [Values(1e5f, 1e6f, 1e7f, 1e8f, 1e9f)] float youngs, [Values(0.3f, 0.45f, 0.49f, 0.4999f)] float poisson, [Values(15f, 30f)] float degrees)
            => HoldsOnSlope(solver, 0, youngs, poisson, degrees);

        // The holding class for a Newton body at two iterations (the runner's soft reference
        // setting). Before friction waited for the last iteration's step it held here too, but
        // also wherever it should have slid (the sliding class below). Measured: at most 0.81 mm
        // in the second second (E 1e5 Pa, nu 0.3, 30 degrees; the softest cubes still settle).
        [Test]
        public void A_newton_cube_at_two_iterations_resting_on_a_slope_holds_at_every_stiffness_and_poisson_ratio(
            [Values(1e5f, 1e6f, 1e7f, 1e8f, 1e9f)] float youngs, [Values(0.3f, 0.45f, 0.49f, 0.4999f)] float poisson, [Values(15f, 30f)] float degrees)
            => HoldsOnSlope(SoftSolver.Newton, 2, youngs, poisson, degrees);

        // A cube on a slope with mu 15 % above tan(angle), solver at iterations (0: the default),
        // moves less than 1 mm over the second second (the first is for settling).
        static void HoldsOnSlope(SoftSolver solver, int iterations, float youngs, float poisson, float degrees)
        {
            float mu = 1.15f * MathF.Tan(degrees * MathF.PI / 180f);
            (SoftBody cube, SoftBodyStats half, SoftBodyStats end, Vector3 down) = TwoSecondsOnSlope(degrees, mu, youngs, poisson, solver, iterations);
            float moved = Vector3.Dot(end.Centroid - half.Centroid, down);
            TestContext.Out.WriteLine($"{solver} x{cube.Iterations} E {youngs:G} nu {poisson} at {degrees} degrees, mu {mu:F3}: moved {moved * 1000:F3} mm in the second second, min J {end.MinJ:F3}");
            Assert.That(MathF.Abs(moved), Is.LessThan(0.001f), "holds");
            Assert.That(end.MinJ, Is.GreaterThan(0.5f));
        }

        // The sliding class: mu = 0.8 tan(angle), the acceleration down the slope over the second
        // second against g (sin - mu cos), at every stiffness and compressibility. At these
        // settings 1 % of friction force is about 4 % of acceleration. The stiff, nearly
        // incompressible Newton cubes slid up to 11 % fast (E 1e9 Pa, nu 0.45 at 15 degrees;
        // 20.8 % measured from 0.5 s): the one linearised Newton step turned them about the
        // slope's normal (2.5-3.4 rad/s), their slips fanned out and the friction down the slope
        // fell short (ImplicitNewtonSolver.KeepContactSpin). Measured since: Newton within 2.4 % (E 1e8 Pa, nu 0.4999, 15 degrees),
        // XPBD within 0.6 % (the soft-friction benchmark, Samples~/Benchmarks).
        [Test]
        public void A_cube_sliding_down_a_slope_accelerates_as_coulomb_friction_says_at_every_stiffness_and_poisson_ratio(
            [Values(SoftSolver.Newton, SoftSolver.Xpbd)] SoftSolver solver,
            [Values(1e5f, 1e6f, 1e7f, 1e8f, 1e9f)] float youngs, [Values(0.3f, 0.45f, 0.49f, 0.4999f)] float poisson, [Values(15f, 30f)] float degrees)
            => SlidesAsCoulombSays(solver, 0, youngs, poisson, degrees);

        // The sliding class for a Newton body at two iterations. The contact pass after each
        // iteration applied friction, the next step pulled the body back to its inertial target
        // while the cone stayed spent, and the support each vertex reported was the larger of the
        // two steps' (their springs held different vertices: up to twice the weight): friction
        // came out 24 % above mu and a cube held on every slope (the soft-friction benchmark:
        // -124 %). Friction now follows the last iteration's step only, bounded by that step's
        // support (SoftBody.SubstepNewton, ShapeContactSolver.ReplaceSupport), and the shares of a
        // sliding patch stay within its whole cone (ShapeContactSolver.HoldPatch). Measured:
        // within 1.0 % (E 1e7 and 1e8 Pa, nu 0.4999, 15 degrees).
        [Test]
        public void A_newton_cube_at_two_iterations_sliding_down_a_slope_accelerates_as_coulomb_friction_says(
            [Values(1e5f, 1e6f, 1e7f, 1e8f, 1e9f)] float youngs, [Values(0.3f, 0.45f, 0.49f, 0.4999f)] float poisson, [Values(15f, 30f)] float degrees)
            => SlidesAsCoulombSays(SoftSolver.Newton, 2, youngs, poisson, degrees);

        // A cube on a slope with mu = 0.8 tan(angle), solver at iterations (0: the default): its
        // acceleration over the second second within 3 % of g (sin - mu cos).
        static void SlidesAsCoulombSays(SoftSolver solver, int iterations, float youngs, float poisson, float degrees)
        {
            float angle = degrees * MathF.PI / 180f, mu = 0.8f * MathF.Tan(angle);
            (SoftBody cube, SoftBodyStats half, SoftBodyStats end, Vector3 down) = TwoSecondsOnSlope(degrees, mu, youngs, poisson, solver, iterations);
            float v1 = Vector3.Dot(half.Momentum / cube.TotalMass, down);
            float v2 = Vector3.Dot(end.Momentum / cube.TotalMass, down);
            float expected = 9.81f * (MathF.Sin(angle) - mu * MathF.Cos(angle)), measured = v2 - v1;
            TestContext.Out.WriteLine($"{solver} x{cube.Iterations} E {youngs:G} nu {poisson} at {degrees} degrees, mu {mu:F3}: {measured:F4} m/s^2 over the second second (closed form {expected:F4}, {(measured / expected - 1) * 100:+0.0;-0.0} %), min J {end.MinJ:F3}");
            Assert.That(measured, Is.EqualTo(expected).Within(3).Percent, "slides at g (sin - mu cos)");
            Assert.That(end.MinJ, Is.GreaterThan(0.5f));
        }

        // A ramp is a box tilted 20 degrees, held in place by being static, kinematic, or dynamic
        // with all six axes locked (Unity's FreezeAll); mu 15 % above tan(angle). The locked
        // dynamic ramp was met as a dynamic body of zero inverse mass: the Newton step's share of
        // it was infinite, the step was skipped, and the cube slid 4.1 m in the second second, as
        // on ice (an XPBD cube held). A body locked on all axes is now met as a static one.
        [TestCase(BodyType.Static, SoftSolver.Newton)]
        [TestCase(BodyType.Kinematic, SoftSolver.Newton)]
        [TestCase(BodyType.Dynamic, SoftSolver.Newton)]
        [TestCase(BodyType.Dynamic, SoftSolver.Xpbd)]
        public void A_cube_holds_on_a_ramp_whatever_holds_the_ramp_in_place(BodyType type, SoftSolver solver)
        {
            float angle = 20f * MathF.PI / 180f, mu = 1.15f * MathF.Tan(angle);
            var world = new World();
            Quaternion tilt = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, angle);
            Vector3 normal = Vector3.Transform(Vector3.UnitY, tilt), down = -Vector3.Transform(Vector3.UnitX, tilt);
            BodyDef rampDef = type == BodyType.Static ? BodyDef.Static(Vector3.Zero) : type == BodyType.Kinematic ? BodyDef.Kinematic(Vector3.Zero) : BodyDef.Dynamic(Vector3.Zero);
            rampDef.Rotation = tilt;
            if (type == BodyType.Dynamic) rampDef.Mass = 1000f;
            BodyHandle ramp = world.CreateBody(rampDef);
            if (type == BodyType.Dynamic) world.SetAxisLocks(ramp, AxisLocks.All);
            world.AddShape(ramp, ShapeDef.Of(ShapeGeometry.Box(new Vector3(2f, 0.1f, 2f))).With((ref ShapeDef s) => s.Friction = mu));
            var def = SoftBodyDef.Of(SoftMesh.Box(new Vector3(0.3f), 3, 3, 3), new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e6f, 0.49f, 1000f), normal * 0.256f);
            def.Rotation = tilt;
            def.Solver = solver;
            def.Friction = mu;
            SoftBody cube = world.GetSoftBody(world.CreateSoftBody(def));
            SoftBodyScenes.Run(world, 60);
            Vector3 half = cube.ComputeStats().Centroid;
            SoftBodyScenes.Run(world, 60);
            float moved = Vector3.Dot(cube.ComputeStats().Centroid - half, down);
            TestContext.Out.WriteLine($"{solver} cube on a {type} ramp: moved {moved * 1000:F3} mm in the second second");
            Assert.That(MathF.Abs(moved), Is.LessThan(0.001f));
        }

        // A Newton cube resting on a slope sticks inside its step (the vertices within reach, with
        // the slope's normal and surface velocity, are part of the saved state, format 7): saved
        // while it sticks, restored into a fresh world and run on, it ends bit-identical to the
        // run that never stopped.
        [Test]
        public void A_newton_cube_sticking_on_a_slope_saves_and_restores_bit_identically()
        {
            (World a, SoftBody cube, _) = CubeOnSlope(30f, 0.8f, 1e7f, 0.45f, SoftSolver.Newton);
            for (int s = 0; s < 60; s++) a.Step(1 / 60f);
            int sticking = 0;
            for (int i = 0; i < cube.X.Length; i++) if (cube.Contacts.Sticks(i, out _, out _)) sticking++;
            Assert.That(sticking, Is.GreaterThan(0), "the cube sticks when the state is saved");
            byte[] state = State.StateRoundTripTests.Save(a);
            for (int s = 0; s < 30; s++) a.Step(1 / 60f);
            (World b, _, _) = CubeOnSlope(30f, 0.8f, 1e7f, 0.45f, SoftSolver.Newton);
            State.StateRoundTripTests.Restore(b, state);
            for (int s = 0; s < 30; s++) b.Step(1 / 60f);
            Assert.That(State.StateRoundTripTests.Save(b), Is.EqualTo(State.StateRoundTripTests.Save(a)));
        }
    }
}
