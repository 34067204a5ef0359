using System;
using System.Numerics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftBodies
{
    /// <summary>
    /// A Newton body's rigid motion is left to inertia: the stiffness-proportional damping and
    /// the energy guard act on its deformation, not on its spin (conservation of angular
    /// momentum, the law a free body obeys); and a Newton body resting on another soft body
    /// stays where it was put.
    /// </summary>
    public class NewtonMomentumTests
    {
        static Vector3 AngularMomentum(SoftBody b)
        {
            Vector3 c = Vector3.Zero;
            float m = 0;
            for (int i = 0; i < b.VertexCount; i++)
            {
                c += b.Masses[i] * b.Positions[i];
                m += b.Masses[i];
            }
            c /= m;
            Vector3 l = Vector3.Zero;
            for (int i = 0; i < b.VertexCount; i++) l += Vector3.Cross(b.Positions[i] - c, b.Masses[i] * b.Velocities[i]);
            return l;
        }

        // A 0.2 m cube in zero gravity turning at about 1 rad/s, 2 s. Measured: |L| within 4 %
        // (implicit Euler's own loss: the same with no damping) and its direction within 1.5
        // degrees. Before the damping left the rigid motion alone, the default damping took 75 %
        // of |L|, tau = 0.05 s 88 %, with 10 substeps 7.5 %; with 4 Newton iterations L turned
        // by 12 degrees.
        [TestCase(0.01f, 1, 0)]
        [TestCase(0.05f, 1, 0)]
        [TestCase(0.01f, 4, 0)]
        [TestCase(0.01f, 1, 10)]
        [TestCase(0f, 1, 0)]
        public void A_spinning_free_newton_body_keeps_its_angular_momentum(float dampingTime, int iterations, int substeps)
        {
            World w = SoftBodyScenes.ZeroGravityWorld();
            var def = SoftBodyDef.Of(SoftMesh.Box(new Vector3(0.2f), 3, 3, 3), new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e6f, 0.45f, 1000f), Vector3.Zero);
            def.Solver = SoftSolver.Newton;
            def.DampingTime = dampingTime;
            def.Iterations = iterations;
            def.Substeps = substeps;
            SoftBody b = w.GetSoftBody(w.CreateSoftBody(def));
            var omega = new Vector3(0.3f, 1f, 0.2f);
            for (int i = 0; i < b.VertexCount; i++) b.SetVertexVelocity(i, Vector3.Cross(omega, b.Positions[i]));
            Vector3 start = AngularMomentum(b);
            SoftBodyScenes.Run(w, 120);
            Vector3 end = AngularMomentum(b);
            float angle = MathF.Acos(Math.Clamp(Vector3.Dot(start, end) / (start.Length() * end.Length()), -1f, 1f)) * 180f / MathF.PI;
            TestContext.Out.WriteLine($"tau {dampingTime}, {iterations} iterations, {substeps} substeps: |L| {start.Length():F5} -> {end.Length():F5}, turned {angle:F1} degrees");
            Assert.That(end.Length(), Is.EqualTo(start.Length()).Within(6).Percent, "|L| of a free body");
            Assert.That(angle, Is.LessThan(5f), "direction of L");
        }

        // A 0.2 m cube (E 1e6 Pa, nu 0.45) set down at rest on a 1 x 0.2 x 1 m slab of the same
        // material on the ground, 5 s: it drifts 3-3.5 mm at most and never rises. Before the
        // damping left the rigid motion alone, a Newton cube rocked ever harder, hopped 6-10 cm
        // and was thrown off the slab, then slid away on the ground (4-6.5 m), on a Newton or an
        // XPBD slab; an XPBD cube on a Newton slab stayed put.
        [TestCase(SoftSolver.Newton, SoftSolver.Newton)]
        [TestCase(SoftSolver.Xpbd, SoftSolver.Newton)]
        [TestCase(SoftSolver.Newton, SoftSolver.Xpbd)]
        public void A_newton_body_resting_on_a_soft_slab_stays_put(SoftSolver slabSolver, SoftSolver cubeSolver)
        {
            World w = SoftBodyScenes.WorldWithGround();
            var material = new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e6f, 0.45f, 1000f);
            var slabDef = SoftBodyDef.Of(SoftMesh.Box(new Vector3(1f, 0.2f, 1f), 6, 2, 6), material, new Vector3(0, 0.106f, 0));
            slabDef.Solver = slabSolver;
            var cubeDef = SoftBodyDef.Of(SoftMesh.Box(new Vector3(0.2f), 3, 3, 3), material, new Vector3(0, 0.323f, 0));
            cubeDef.Solver = cubeSolver;
            SoftBody slab = w.GetSoftBody(w.CreateSoftBody(slabDef)), cube = w.GetSoftBody(w.CreateSoftBody(cubeDef));
            Vector3 Centre(SoftBody b)
            {
                Vector3 c = Vector3.Zero;
                foreach (Vector3 p in b.Positions) c += p;
                return c / b.VertexCount;
            }
            Vector3 start = Centre(cube);
            float mostDrift = 0, mostRise = 0;
            for (int n = 0; n < 300; n++)
            {
                w.Step(SoftBodyScenes.Dt);
                Vector3 d = Centre(cube) - start;
                mostDrift = MathF.Max(mostDrift, new Vector2(d.X, d.Z).Length());
                mostRise = MathF.Max(mostRise, d.Y);
            }
            float top = float.MinValue, bottom = float.MaxValue;
            foreach (Vector3 p in slab.Positions) top = MathF.Max(top, p.Y);
            foreach (Vector3 p in cube.Positions) bottom = MathF.Min(bottom, p.Y);
            TestContext.Out.WriteLine($"{slabSolver} slab, {cubeSolver} cube: drifted at most {mostDrift * 1000:F1} mm, rose at most {mostRise * 1000:F1} mm; cube bottom - slab top {1000 * (bottom - top):F1} mm");
            Assert.That(mostDrift, Is.LessThan(0.01f), "the cube does not walk");
            Assert.That(mostRise, Is.LessThan(0.005f), "nor hop");
            Assert.That(bottom - top, Is.GreaterThan(-0.01f), "and it stays on the slab");
        }
    }
}
