using System;
using System.Diagnostics;
using System.Numerics;

namespace Fulcrum.Benchmarks.Peers
{
    /// <summary>
    /// Runs one engine on one scene: warm-up steps, then timed steps, each timed alone; the
    /// accuracy figures come from the poses, computed the same way for every engine and kept out
    /// of the timed region.
    /// </summary>
    public static class PeerRun
    {
        /// <summary>
        /// Runs a small throwaway pile for at least <paramref name="seconds"/> of wall time and
        /// <paramref name="minSteps"/> steps so that
        /// the engine's code is fully JIT-compiled (tiered, with PGO) before any scene is timed, without
        /// spending the timed scenes' own warm-up steps on it.
        /// </summary>
        public static void WarmUp(IPeerEngine engine, PeerSettings settings, double seconds, int minSteps)
        {
            PeerScene scene = PeerScene.Pile(4, 4, 0, 1);
            engine.Build(scene, settings);
            long start = Stopwatch.GetTimestamp();
            // Tier-1 recompilation runs on a background thread that a busy machine can starve, so
            // a minimum step count backs up the wall-time minimum.
            for (int step = 0; step < 3000 && (step < minSteps || Stopwatch.GetElapsedTime(start).TotalSeconds < seconds); step++)
                engine.Step(settings.Dt);
            engine.Dispose();
        }

        public static PeerResult Measure(IPeerEngine engine, PeerScene scene, PeerSettings settings)
        {
            engine.Build(scene, settings);
            int total = scene.WarmupSteps + scene.MeasuredSteps;
            var cpuMs = new double[scene.MeasuredSteps];
            var wallMs = new double[scene.MeasuredSteps];
            double maxPenetration = 0;
            bool finite = true;
            for (int step = 0; step < total; step++)
            {
                double cpuStart = ThreadClock.NowMs();
                long start = Stopwatch.GetTimestamp();
                engine.Step(settings.Dt);
                long end = Stopwatch.GetTimestamp();
                double cpuEnd = ThreadClock.NowMs();
                if (step >= scene.WarmupSteps)
                {
                    cpuMs[step - scene.WarmupSteps] = cpuEnd - cpuStart;
                    wallMs[step - scene.WarmupSteps] = (end - start) * 1000.0 / Stopwatch.Frequency;
                }
                float groundTop = scene.Ground.Center.Y + scene.Ground.HalfExtents.Y;
                for (int i = 0; i < scene.Boxes.Count; i++)
                {
                    engine.ReadPose(i, out Vector3 p, out Quaternion q);
                    if (!(float.IsFinite(p.X) && float.IsFinite(p.Y) && float.IsFinite(p.Z))) { finite = false; continue; }
                    maxPenetration = Math.Max(maxPenetration, groundTop - PeerBox.LowestY(p, q, scene.Boxes[i].HalfExtents));
                }
            }

            double drift = double.NaN, sink = double.NaN;
            if (scene.Tracked >= 0)
            {
                engine.ReadPose(scene.Tracked, out Vector3 end, out _);
                Vector3 start = scene.Boxes[scene.Tracked].Center;
                drift = Math.Sqrt((end.X - start.X) * (end.X - start.X) + (end.Z - start.Z) * (end.Z - start.Z));
                sink = start.Y - end.Y;
            }
            string name = engine.Name;
            engine.Dispose();

            Array.Sort(cpuMs);
            Array.Sort(wallMs);
            return new PeerResult
            {
                Engine = name,
                Scene = scene.Name,
                Bodies = scene.Boxes.Count,
                MedianMs = Percentile(cpuMs, 0.5),
                P95Ms = Percentile(cpuMs, 0.95),
                WallMedianMs = Percentile(wallMs, 0.5),
                Drift = drift,
                Sink = sink,
                MaxGroundPenetration = maxPenetration,
                Finite = finite,
            };
        }

        // Nearest-rank percentile of sorted values.
        static double Percentile(double[] sorted, double q)
        {
            if (sorted.Length == 0) return double.NaN;
            int rank = (int)Math.Ceiling(q * sorted.Length) - 1;
            return sorted[Math.Clamp(rank, 0, sorted.Length - 1)];
        }
    }
}
