using System;
using System.Numerics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftBodies
{
    /// <summary>
    /// The eight-lane tet kernels (.NET with AVX) against the scalar ones: the same operations
    /// in the same order, so positions, velocities and multipliers must agree bit for bit. The
    /// scene has every lane case: fully pinned tets (skipped), tets with a pinned vertex, tets
    /// attached to a rigid body (no torque-free projection), ground contact and a large
    /// deformation (so the deviatoric constraint is far from its rest cone). Where the wide
    /// kernels do not exist (netstandard2.1) both runs are scalar and the test holds trivially.
    /// </summary>
    public class WideKernelTests
    {
        static World Scene(int threads, out SoftBody body)
        {
            WorldSettings settings = WorldSettings.Default;
            settings.Threads = threads;
            var world = new World(settings);
            BodyHandle ground = world.CreateBody(BodyDef.Static(Vector3.Zero));
            world.AddShape(ground, ShapeDef.Of(ShapeGeometry.Plane(Vector3.UnitY, 0)));
            BodyHandle crate = world.CreateBody(BodyDef.Dynamic(new Vector3(0.45f, 0.6f, 0)));
            ShapeDef box = ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.1f, 0.1f, 0.1f)));
            box.Density = 500f;
            world.AddShape(crate, box);
            var def = SoftBodyDef.Of(SoftMesh.Box(new Vector3(0.8f, 0.4f, 0.4f), 8, 4, 4), MaterialPresets.Rubber, new Vector3(0, 0.6f, 0));
            def.InitialDeformation = new Fulcrum.Mathematics.Mat3(new Vector3(1.3f, 0.1f, 0), new Vector3(0, 0.8f, 0.2f), new Vector3(0.1f, 0, 1.1f));
            def.LinearVelocity = new Vector3(0.5f, -1f, 0.2f);
            def.Iterations = 2; // multipliers start non-zero in the second iteration
            def.Pins = new[]
            {
                SoftPin.ToWorld(new Vector3(-0.4f, -0.2f, -0.2f), new Vector3(-0.3f, 0.2f, 0.2f)),
                SoftPin.ToBody(new Vector3(0.4f, -0.2f, -0.2f), new Vector3(0.4f, 0.2f, 0.2f), crate),
            };
            body = world.GetSoftBody(world.CreateSoftBody(def));
            return world;
        }

        static void Run(bool wide, int threads, out Vector3[] x, out Vector3[] v, out Vector2[] lambda)
        {
            bool was = TetStream.WideKernels;
            try
            {
#if NET
                TetStream.WideKernels = wide && Lanes8.IsSupported;
#endif
                World world = Scene(threads, out SoftBody body);
                for (int i = 0; i < 20; i++) world.Step(1f / 60f);
                x = body.Positions.ToArray();
                v = body.Velocities.ToArray();
                lambda = (Vector2[])body.TetLambda.Clone();
                world.StopThreads();
            }
            finally
            {
                TetStream.WideKernels = was;
            }
        }

        static int Differences(Vector3[] a, Vector3[] b)
        {
            int n = 0;
            for (int i = 0; i < a.Length; i++)
            {
                if (BitConverter.SingleToInt32Bits(a[i].X) != BitConverter.SingleToInt32Bits(b[i].X)
                    || BitConverter.SingleToInt32Bits(a[i].Y) != BitConverter.SingleToInt32Bits(b[i].Y)
                    || BitConverter.SingleToInt32Bits(a[i].Z) != BitConverter.SingleToInt32Bits(b[i].Z)) n++;
            }
            return n;
        }

        [TestCase(1)]
        [TestCase(2)]
        public void Wide_kernels_match_the_scalar_ones_bit_for_bit(int threads)
        {
            Run(false, 1, out Vector3[] x0, out Vector3[] v0, out Vector2[] l0);
            Run(true, threads, out Vector3[] x1, out Vector3[] v1, out Vector2[] l1);
            // The scene must have moved and deformed for the comparison to mean anything.
            Assert.That(Vector3.Distance(x0[x0.Length - 1], x0[0]), Is.GreaterThan(0.5f));
            Assert.That(Differences(x0, x1), Is.EqualTo(0), "positions");
            Assert.That(Differences(v0, v1), Is.EqualTo(0), "velocities");
            var lx0 = Array.ConvertAll(l0, l => new Vector3(l.X, l.Y, 0));
            var lx1 = Array.ConvertAll(l1, l => new Vector3(l.X, l.Y, 0));
            Assert.That(Differences(lx0, lx1), Is.EqualTo(0), "multipliers");
        }
    }
}
