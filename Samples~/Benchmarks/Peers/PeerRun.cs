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
        /// Brings an engine's code to steady state before anything is timed: a small falling pile
        /// (every contact path), then a small resting pyramid in blocks of 100 steps until a block's
        /// median step time stops improving (2 %) for three blocks and at least
        /// <paramref name="seconds"/> have passed. Tier-1 recompilation with PGO runs on a background
        /// thread that a busy machine starves, so a fixed step count is not enough.
        /// Returns the wall seconds spent.
        /// </summary>
        public static double WarmUp(Func<IPeerEngine> create, PeerSettings settings, double seconds, int pileSteps)
        {
            long start = Stopwatch.GetTimestamp();
            using (IPeerEngine pile = create())
            {
                pile.Build(PeerScene.Pile(4, 4, 0, 1), settings);
                for (int step = 0; step < pileSteps; step++) pile.Step(settings.Dt);
            }
            using (IPeerEngine pyramid = create())
            {
                pyramid.Build(PeerScene.Pyramid(5, 0, 1), settings);
                var block = new double[100];
                double best = double.MaxValue;
                int stale = 0;
                for (int b = 0; b < 100 && (stale < 3 || Stopwatch.GetElapsedTime(start).TotalSeconds < seconds); b++)
                {
                    for (int k = 0; k < block.Length; k++)
                    {
                        double t = ThreadClock.NowMs();
                        pyramid.Step(settings.Dt);
                        block[k] = ThreadClock.NowMs() - t;
                    }
                    Array.Sort(block);
                    double median = block[block.Length / 2];
                    if (median < 0.98 * best) { best = median; stale = 0; }
                    else stale++;
                }
            }
            return Stopwatch.GetElapsedTime(start).TotalSeconds;
        }

        public static PeerResult Measure(IPeerEngine engine, PeerScene scene, PeerSettings settings)
        {
            engine.Build(scene, settings);
            int total = scene.WarmupSteps + scene.MeasuredSteps;
            var cpuMs = new double[scene.MeasuredSteps];
            var wallMs = new double[scene.MeasuredSteps];
            double maxPenetration = 0;
            bool finite = true;
            long allocated = 0;
            for (int step = 0; step < total; step++)
            {
                long bytes = GC.GetAllocatedBytesForCurrentThread();
                double cpuStart = ThreadClock.NowMs();
                long start = Stopwatch.GetTimestamp();
                engine.Step(settings.Dt);
                long end = Stopwatch.GetTimestamp();
                double cpuEnd = ThreadClock.NowMs();
                if (step >= scene.WarmupSteps)
                {
                    allocated += GC.GetAllocatedBytesForCurrentThread() - bytes;
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
                BytesPerStep = scene.MeasuredSteps > 0 ? (double)allocated / scene.MeasuredSteps : 0,
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
