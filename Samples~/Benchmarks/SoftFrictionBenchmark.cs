using System;
using System.Diagnostics;
using System.IO;
using System.Numerics;
using Fulcrum.SoftBodies;

namespace Fulcrum.Benchmarks
{
    /// <summary>
    /// Coulomb friction of a soft cube on a slope against its closed forms, across stiffness and
    /// compressibility, for both soft solvers: with mu = 0.8 tan(angle) it slides at
    /// a = g (sin - mu cos), with mu = 1.15 tan(angle) it holds. The acceleration is measured over
    /// the second second (after the landing's transient); the hold as the distance moved down
    /// the slope in the second second. The error in a is about four times the error in the
    /// friction force at these settings (a is the small difference of gravity and friction).
    /// </summary>
    public sealed class SoftFrictionBenchmark : IBenchmark
    {
        public string Name => "soft-friction";

        public string Description => "soft cube on a slope (E 1e5-1e9 Pa, nu 0.3-0.4999, 15 and 30 degrees): sliding acceleration vs g (sin - mu cos), hold drift; XPBD and Newton (1 and 2 iterations)";

        public void Run(TextWriter output, bool quick)
        {
            float[] youngs = quick ? new[] { 1e6f, 1e9f } : new[] { 1e5f, 1e6f, 1e7f, 1e8f, 1e9f };
            float[] poisson = quick ? new[] { 0.49f } : new[] { 0.3f, 0.45f, 0.49f, 0.4999f };
            float[] degrees = quick ? new[] { 15f } : new[] { 15f, 30f };
            var columns = new (SoftSolver Solver, int Iterations)[] { (SoftSolver.Xpbd, 1), (SoftSolver.Newton, 1), (SoftSolver.Newton, 2) };
            output.WriteLine("0.3 m cube (3 cells, 1000 kg/m^3), defaults otherwise (60 Hz). Sliding: mu = 0.8 tan(angle), error of the acceleration over the second second");
            output.WriteLine("against g (sin - mu cos). Holding: mu = 1.15 tan(angle), mm moved down the slope in the second second. Worst |error| per column at the end.");
            output.WriteLine();
            output.Write("| angle | E (Pa) | nu |");
            foreach (var c in columns) output.Write($" {c.Solver} x{c.Iterations}: slide error / hold mm |");
            output.WriteLine(" ms/step (Newton x1 slide) |");
            output.Write("|---|---|---|");
            foreach (var _ in columns) output.Write("---|");
            output.WriteLine("---|");
            var worstSlide = new float[columns.Length];
            var worstHold = new float[columns.Length];
            foreach (float angle in degrees)
            foreach (float e in youngs)
            foreach (float nu in poisson)
            {
                output.Write($"| {angle:F0} | {e:E0} | {nu} |");
                double ms = 0;
                for (int k = 0; k < columns.Length; k++)
                {
                    float a = SlideError(angle, e, nu, columns[k].Solver, columns[k].Iterations, out double stepMs);
                    float hold = HoldDrift(angle, e, nu, columns[k].Solver, columns[k].Iterations);
                    if (k == 1) ms = stepMs;
                    worstSlide[k] = MathF.Max(worstSlide[k], MathF.Abs(a));
                    worstHold[k] = MathF.Max(worstHold[k], MathF.Abs(hold));
                    output.Write($" {Percent(a)} / {hold * 1000:F2} |");
                }
                output.WriteLine($" {ms:F2} |");
            }
            output.Write("| worst | | |");
            for (int k = 0; k < columns.Length; k++) output.Write($" {worstSlide[k] * 100:F1} % / {worstHold[k] * 1000:F2} |");
            output.WriteLine(" |");
        }

        // A signed percentage with one decimal, "0.0 %" for anything that rounds to zero.
        static string Percent(float fraction)
        {
            float p = MathF.Round(fraction * 1000f) / 10f;
            return p == 0f ? "0.0 %" : $"{p:+0.0;-0.0} %";
        }

        static (World, SoftBody, Vector3) Cube(float degrees, float mu, float youngs, float poisson, SoftSolver solver, int iterations)
        {
            float angle = degrees * MathF.PI / 180f;
            var world = new World(WorldSettings.Default);
            var normal = new Vector3(-MathF.Sin(angle), MathF.Cos(angle), 0);
            BodyHandle ground = world.CreateBody(BodyDef.Static(Vector3.Zero));
            ShapeDef plane = ShapeDef.Of(ShapeGeometry.Plane(normal, 0f));
            plane.Friction = mu;
            world.AddShape(ground, plane);
            var def = SoftBodyDef.Of(SoftMesh.Box(new Vector3(0.3f), 3, 3, 3), new NeoHookeanMaterial(MaterialModel.StableNeoHookean, youngs, poisson, 1000f), normal * 0.156f);
            def.Rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, angle);
            def.Solver = solver;
            def.Iterations = iterations;
            def.Friction = mu;
            SoftBody cube = world.GetSoftBody(world.CreateSoftBody(def));
            return (world, cube, new Vector3(-MathF.Cos(angle), -MathF.Sin(angle), 0));
        }

        // Relative error of the acceleration down the slope between 1 s and 2 s.
        static float SlideError(float degrees, float youngs, float poisson, SoftSolver solver, int iterations, out double msPerStep)
        {
            float angle = degrees * MathF.PI / 180f, mu = 0.8f * MathF.Tan(angle);
            (World world, SoftBody cube, Vector3 down) = Cube(degrees, mu, youngs, poisson, solver, iterations);
            for (int i = 0; i < 60; i++) world.Step(1f / 60f);
            float v0 = Vector3.Dot(cube.ComputeStats().Momentum / cube.TotalMass, down);
            long t = Stopwatch.GetTimestamp();
            for (int i = 0; i < 60; i++) world.Step(1f / 60f);
            msPerStep = (Stopwatch.GetTimestamp() - t) * 1000.0 / Stopwatch.Frequency / 60;
            float v1 = Vector3.Dot(cube.ComputeStats().Momentum / cube.TotalMass, down);
            float expected = 9.81f * (MathF.Sin(angle) - mu * MathF.Cos(angle));
            return (v1 - v0) / expected - 1f;
        }

        // Metres moved down the slope in the second second where friction should hold.
        static float HoldDrift(float degrees, float youngs, float poisson, SoftSolver solver, int iterations)
        {
            float mu = 1.15f * MathF.Tan(degrees * MathF.PI / 180f);
            (World world, SoftBody cube, Vector3 down) = Cube(degrees, mu, youngs, poisson, solver, iterations);
            for (int i = 0; i < 60; i++) world.Step(1f / 60f);
            Vector3 settled = cube.ComputeStats().Centroid;
            for (int i = 0; i < 60; i++) world.Step(1f / 60f);
            return Vector3.Dot(cube.ComputeStats().Centroid - settled, down);
        }
    }
}
