using System;
using System.Numerics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftScenes
{
    public class ClothDrapeTests
    {
        // cloth-drape.json: a 1.5 m square cloth shell (16 x 16 cells, 0.5 mm thick, E = 1e7 Pa,
        // 300 kg/m^3: 0.15 kg/m^2, damping time 1 ms) released flat 0.2 m above a static 0.4 m
        // ball resting on the ground.
        const float Radius = 0.4f, Half = 0.75f, Seconds = 3f;
        static readonly Vector3 Ball = new Vector3(0, 0.4f, 0);

        [Test]
        public void Cloth_dropped_on_a_ball_drapes_over_it_without_passing_through_or_stretching()
        {
            SoftSceneRun run = SoftSceneRun.Load("cloth-drape");
            SoftBody cloth = run.Body;
            Assert.That(cloth.IsShell, Is.True);
            int centre = Nearest(cloth.Mesh.Vertices, Vector3.Zero);
            float collision = cloth.CollisionRadius;
            int steps = run.StepsIn(Seconds);
            float deepest = float.MaxValue, worstStretch = 0f;
            for (int n = 0; n < steps; n++)
            {
                run.Step();
                ReadOnlySpan<Vector3> x = cloth.Positions;
                for (int i = 0; i < x.Length; i++) deepest = MathF.Min(deepest, (x[i] - Ball).Length() - Radius);
                worstStretch = MathF.Max(worstStretch, MaxEdgeStretch(cloth));
            }
            Assert.That(run.AllFinite(), Is.True);
            float restingStretch = MaxEdgeStretch(cloth), endSpeed = RmsSpeed(cloth);

            ReadOnlySpan<Vector3> p = cloth.Positions;
            float centreHeight = p[centre].Y, top = Ball.Y + Radius;
            float highestCorner = float.MinValue, lowest = float.MaxValue;
            foreach (Vector3 corner in new[] { new Vector3(-Half, 0, -Half), new Vector3(Half, 0, -Half), new Vector3(-Half, 0, Half), new Vector3(Half, 0, Half) })
                highestCorner = MathF.Max(highestCorner, p[Nearest(cloth.Mesh.Vertices, corner)].Y);
            for (int i = 0; i < p.Length; i++) lowest = MathF.Min(lowest, p[i].Y);
            SoftBodyStats s = cloth.ComputeStats();
            TestContext.Out.WriteLine($"cloth-drape: centre vertex at y {centreHeight:F4} m (ball top {top} m + collision radius {collision} m); deepest vertex {deepest * 1000:F2} mm from the ball's surface; highest corner y {highestCorner:F3} m, lowest vertex y {lowest:F4} m; worst edge stretch {worstStretch:P2} (during the fall), {restingStretch:P2} at rest; rms speed at the end {endSpeed:F4} m/s; kinetic {s.KineticEnergy:E2} J");

            Assert.That(centreHeight, Is.EqualTo(top + collision).Within(0.01f), "the centre rests on the ball's top");
            Assert.That(deepest, Is.GreaterThan(-0.01f), "no vertex more than 1 cm inside the ball");
            Assert.That(highestCorner, Is.LessThan(top - 0.3f), "the corners hang well below the top");
            Assert.That(lowest, Is.GreaterThan(-0.01f), "nothing passes through the ground");
            // The membrane's own sag is tiny (E t = 5000 N/m against 0.15 kg/m^2); what stretch
            // there is comes from the solver. Stiffness-proportional damping scales every XPBD
            // correction by h / (h + dampingTime): with the engine's 0.01 s default (1/7 at 10
            // substeps) a resting sheet stays 10.4 % long at its top edges; the file's 1 ms
            // (h / (h + 1 ms) = 0.62) leaves 4.3 % (4.8 % with 0, 1.7 % with 30 substeps as well).
            Assert.That(restingStretch, Is.LessThan(0.06f), "edges at rest stretch less than 6 %");
            Assert.That(worstStretch, Is.LessThan(0.18f), "and less than 18 % when the sheet lands");
            Assert.That(endSpeed, Is.LessThan(0.05f), "settled (it landed at 2 m/s)");
        }

        static int Nearest(ReadOnlySpan<Vector3> points, Vector3 to)
        {
            int best = 0;
            for (int i = 1; i < points.Length; i++)
                if ((points[i] - to).LengthSquared() < (points[best] - to).LengthSquared()) best = i;
            return best;
        }

        // Largest relative lengthening of a triangle edge over its rest length.
        internal static float MaxEdgeStretch(SoftBody body)
        {
            ReadOnlySpan<Vector3> rest = body.Mesh.Vertices, x = body.Positions;
            ReadOnlySpan<int> tris = body.Mesh.Triangles;
            float worst = 0f;
            for (int t = 0; t < tris.Length; t += 3)
                for (int k = 0; k < 3; k++)
                {
                    int a = tris[t + k], b = tris[t + (k + 1) % 3];
                    worst = MathF.Max(worst, (x[a] - x[b]).Length() / (rest[a] - rest[b]).Length() - 1f);
                }
            return worst;
        }

        static float RmsSpeed(SoftBody body)
        {
            ReadOnlySpan<Vector3> v = body.Velocities;
            float sum = 0f;
            for (int i = 0; i < v.Length; i++) sum += v[i].LengthSquared();
            return MathF.Sqrt(sum / v.Length);
        }
    }
}
