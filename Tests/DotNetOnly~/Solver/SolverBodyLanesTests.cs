using System;
using System.Numerics;
using Fulcrum.Dynamics;
using Fulcrum.Mathematics;
using NUnit.Framework;

namespace Fulcrum.Tests.Solver
{
    /// <summary>The transposing gather and scatter of solver bodies (AVX, eight lanes).</summary>
    public class SolverBodyLanesTests
    {
        static SolverBody[] Bodies(int count)
        {
            var random = new Random(7);
            float R() => (float)(random.NextDouble() * 2 - 1);
            var bodies = new SolverBody[count];
            for (int i = 0; i < count; i++)
            {
                bodies[i] = new SolverBody
                {
                    LinearVelocity = new Vector3(R(), R(), R()),
                    InverseMass = 1f + i,
                    AngularVelocity = new Vector3(R(), R(), R()),
                    IsDynamic = i % 3 == 0 ? 0 : 1,
                    InverseInertia = new Mat3 { C0 = new Vector3(R(), R(), R()), C1 = new Vector3(R(), R(), R()), C2 = new Vector3(R(), R(), R()) },
                    DeltaPosition = new Vector3(R(), R(), R()),
                    DeltaRotation = Quaternion.Normalize(new Quaternion(R(), R(), R(), R())),
                };
            }
            return bodies;
        }

        [Test]
        public void Transposed_loads_give_each_lane_its_own_body_fields()
        {
            if (!SolverBodyLanes.IsSupported) Assert.Ignore("no AVX with eight-float vectors: the lane-by-lane path runs");
            SolverBody[] bodies = Bodies(12);
            int[] lanes = { 5, 0, 11, 2, 7, 3, 9, 1 };
            int[] laneBodies = new int[16];
            for (int k = 0; k < 8; k++) laneBodies[2 * k] = lanes[k];
            ref float b0 = ref SolverBodyLanes.Body(bodies, laneBodies, 0);
            ref float b1 = ref SolverBodyLanes.Body(bodies, laneBodies, 2);
            ref float b2 = ref SolverBodyLanes.Body(bodies, laneBodies, 4);
            ref float b3 = ref SolverBodyLanes.Body(bodies, laneBodies, 6);
            ref float b4 = ref SolverBodyLanes.Body(bodies, laneBodies, 8);
            ref float b5 = ref SolverBodyLanes.Body(bodies, laneBodies, 10);
            ref float b6 = ref SolverBodyLanes.Body(bodies, laneBodies, 12);
            ref float b7 = ref SolverBodyLanes.Body(bodies, laneBodies, 14);
            SolverBodyLanes.Load(ref b0, ref b1, ref b2, ref b3, ref b4, ref b5, ref b6, ref b7, SolverBodyLanes.Linear,
                out Vector<float> vx, out Vector<float> vy, out Vector<float> vz, out Vector<float> m);
            SolverBodyLanes.Load(ref b0, ref b1, ref b2, ref b3, ref b4, ref b5, ref b6, ref b7, SolverBodyLanes.Displacement,
                out _, out Vector<float> px, out Vector<float> py, out Vector<float> pz);
            SolverBodyLanes.Load(ref b0, ref b1, ref b2, ref b3, ref b4, ref b5, ref b6, ref b7, SolverBodyLanes.Rotation,
                out Vector<float> qx, out _, out _, out Vector<float> qw);
            for (int k = 0; k < 8; k++)
            {
                SolverBody b = bodies[lanes[k]];
                Assert.That(vx[k], Is.EqualTo(b.LinearVelocity.X));
                Assert.That(vy[k], Is.EqualTo(b.LinearVelocity.Y));
                Assert.That(vz[k], Is.EqualTo(b.LinearVelocity.Z));
                Assert.That(m[k], Is.EqualTo(b.InverseMass));
                Assert.That(px[k], Is.EqualTo(b.DeltaPosition.X));
                Assert.That(py[k], Is.EqualTo(b.DeltaPosition.Y));
                Assert.That(pz[k], Is.EqualTo(b.DeltaPosition.Z));
                Assert.That(qx[k], Is.EqualTo(b.DeltaRotation.X));
                Assert.That(qw[k], Is.EqualTo(b.DeltaRotation.W));
            }
        }

        [Test]
        public void Transposed_store_writes_only_the_flagged_lanes_and_nothing_else()
        {
            if (!SolverBodyLanes.IsSupported) Assert.Ignore("no AVX with eight-float vectors: the lane-by-lane path runs");
            SolverBody[] bodies = Bodies(8);
            SolverBody[] before = (SolverBody[])bodies.Clone();
            int[] laneBodies = new int[16];
            for (int k = 0; k < 8; k++) laneBodies[2 * k] = 7 - k;
            ref float b0 = ref SolverBodyLanes.Body(bodies, laneBodies, 0);
            ref float b1 = ref SolverBodyLanes.Body(bodies, laneBodies, 2);
            ref float b2 = ref SolverBodyLanes.Body(bodies, laneBodies, 4);
            ref float b3 = ref SolverBodyLanes.Body(bodies, laneBodies, 6);
            ref float b4 = ref SolverBodyLanes.Body(bodies, laneBodies, 8);
            ref float b5 = ref SolverBodyLanes.Body(bodies, laneBodies, 10);
            ref float b6 = ref SolverBodyLanes.Body(bodies, laneBodies, 12);
            ref float b7 = ref SolverBodyLanes.Body(bodies, laneBodies, 14);
            var x = new Vector<float>(new float[] { 10, 11, 12, 13, 14, 15, 16, 17 });
            Vector<float> y = x + new Vector<float>(10), z = x + new Vector<float>(20), w = x + new Vector<float>(30);
            const int write = 0b1010_0110;
            SolverBodyLanes.Store(ref b0, ref b1, ref b2, ref b3, ref b4, ref b5, ref b6, ref b7, write, SolverBodyLanes.Angular, x, y, z, w);
            for (int k = 0; k < 8; k++)
            {
                SolverBody now = bodies[7 - k], then = before[7 - k];
                bool written = (write & (1 << k)) != 0;
                Vector3 expected = written ? new Vector3(10 + k, 20 + k, 30 + k) : then.AngularVelocity;
                Assert.That(now.AngularVelocity, Is.EqualTo(expected), $"lane {k}");
                Assert.That(now.IsDynamic, Is.EqualTo(written ? BitConverter.SingleToInt32Bits(40 + k) : then.IsDynamic), $"lane {k}");
                Assert.That(now.LinearVelocity, Is.EqualTo(then.LinearVelocity));
                Assert.That(now.InverseMass, Is.EqualTo(then.InverseMass));
                Assert.That(now.InverseInertia, Is.EqualTo(then.InverseInertia));
            }
        }
    }
}
