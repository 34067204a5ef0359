using System;
using System.Collections.Generic;
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

        /// <summary>
        /// One run over <paramref name="scenes"/>: every engine on a scene before the next scene,
        /// in roster order or reversed, alternating between runs and scenes (so a slow spell of a
        /// shared machine does not land on one engine). Returns the rows in roster order, phase by
        /// phase, scene by scene.
        /// </summary>
        public static List<PeerResult> MeasureRun(IReadOnlyList<Func<IPeerEngine>> engines, PeerScene[] scenes, PeerSettings settings, int run)
        {
            var rows = new List<PeerResult>();
            for (int sc = 0; sc < scenes.Length; sc++)
            {
                var measured = new PeerResult[engines.Count][];
                bool reverse = ((run + sc) & 1) == 1;
                for (int n = 0; n < engines.Count; n++)
                {
                    int e = reverse ? engines.Count - 1 - n : n;
                    measured[e] = Measure(engines[e](), scenes[sc], settings);
                }
                for (int f = 0; f < scenes[sc].Phases.Count; f++)
                    for (int e = 0; e < engines.Count; e++) rows.Add(measured[e][f]);
            }
            return rows;
        }

        /// <summary>
        /// Builds <paramref name="scene"/> in <paramref name="engine"/>, runs its warm-up and phases
        /// and returns one result per phase. Every step is timed alone; the poses are read after
        /// every step (outside the timing) for the penetration, speed and finiteness figures.
        /// </summary>
        public static PeerResult[] Measure(IPeerEngine engine, PeerScene scene, PeerSettings settings)
        {
            engine.Build(scene, settings);
            int total = scene.WarmupSteps + scene.MeasuredSteps;
            int phases = scene.Phases.Count;
            bool cpuTime = engine.Threads == 1 && ThreadClock.IsCpuTime;
            var ms = new double[phases][];
            var wallMs = new double[phases][];
            var allocated = new long[phases];
            var processAllocated = new long[phases];
            var maxPenetration = new double[phases];
            var drift = new double[phases];
            var sink = new double[phases];
            var endSpeed = new double[phases];
            var processCpu = new double[phases];
            var stages = new double[phases][];
            var fulcrum = engine as FulcrumPeer;
            for (int f = 0; f < phases; f++)
            {
                ms[f] = new double[scene.Phases[f].Steps];
                wallMs[f] = new double[scene.Phases[f].Steps];
                drift[f] = sink[f] = double.NaN;
                stages[f] = new double[StepProfile.StageCount];
            }
            var previous = new Vector3[scene.Boxes.Count];
            for (int i = 0; i < previous.Length; i++) previous[i] = scene.Boxes[i].Center;
            bool finite = true;
            float groundTop = scene.Ground.Center.Y + scene.Ground.HalfExtents.Y;
            for (int step = 0; step < total; step++)
            {
                int timed = step - scene.WarmupSteps;
                int phase = -1;
                for (int f = 0; f < phases; f++)
                    if (scene.Phases[f].Contains(timed)) phase = f;
                // The process-wide count is exact only with precise: true, which briefly
                // suspends every thread: read it at the phase's ends, not around every step
                // (nothing between the steps allocates).
                if (phase >= 0 && timed == scene.Phases[phase].Start) processAllocated[phase] = -GC.GetTotalAllocatedBytes(true);
                long bytes = GC.GetAllocatedBytesForCurrentThread();
                double processStart = ThreadClock.ProcessNowMs();
                double cpuStart = ThreadClock.NowMs();
                long start = Stopwatch.GetTimestamp();
                engine.Step(settings.Dt);
                long end = Stopwatch.GetTimestamp();
                double cpuEnd = ThreadClock.NowMs();
                double processEnd = ThreadClock.ProcessNowMs();
                if (phase < 0)
                {
                    ReadPoses(engine, scene, previous, groundTop, ref finite, out _, out _);
                    continue;
                }
                allocated[phase] += GC.GetAllocatedBytesForCurrentThread() - bytes;
                int k = timed - scene.Phases[phase].Start;
                double wall = (end - start) * 1000.0 / Stopwatch.Frequency;
                ms[phase][k] = cpuTime ? cpuEnd - cpuStart : wall;
                wallMs[phase][k] = wall;
                processCpu[phase] += processEnd - processStart;
                if (fulcrum != null)
                {
                    StepProfile profile = fulcrum.LastStepProfile;
                    for (int stage = 0; stage < StepProfile.StageCount; stage++) stages[phase][stage] += profile[(StepStage)stage];
                }
                ReadPoses(engine, scene, previous, groundTop, ref finite, out double penetration, out double moved);
                maxPenetration[phase] = Math.Max(maxPenetration[phase], penetration);
                if (k == scene.Phases[phase].Steps - 1)
                {
                    processAllocated[phase] += GC.GetTotalAllocatedBytes(true);
                    endSpeed[phase] = moved / (scene.Boxes.Count * settings.Dt);
                    if (scene.Tracked >= 0)
                    {
                        engine.ReadPose(scene.Tracked, out Vector3 at, out _);
                        Vector3 from = scene.Boxes[scene.Tracked].Center;
                        drift[phase] = Math.Sqrt((at.X - from.X) * (at.X - from.X) + (at.Z - from.Z) * (at.Z - from.Z));
                        sink[phase] = from.Y - at.Y;
                    }
                }
            }
            string name = engine.Name;
            int threads = engine.Threads;
            engine.Dispose();

            var results = new PeerResult[phases];
            for (int f = 0; f < phases; f++)
            {
                int steps = scene.Phases[f].Steps;
                double sum = 0, wallSum = 0;
                foreach (double t in ms[f]) sum += t;
                foreach (double t in wallMs[f]) wallSum += t;
                Array.Sort(ms[f]);
                Array.Sort(wallMs[f]);
                results[f] = new PeerResult
                {
                    Engine = name,
                    Scene = scene.Phases[f].Name,
                    Bodies = scene.Boxes.Count,
                    Threads = threads,
                    CpuTime = cpuTime,
                    MeanMs = steps > 0 ? sum / steps : double.NaN,
                    MedianMs = Percentile(ms[f], 0.5),
                    P95Ms = Percentile(ms[f], 0.95),
                    WallMeanMs = steps > 0 ? wallSum / steps : double.NaN,
                    ProcessCpuMs = steps > 0 ? processCpu[f] / steps : double.NaN,
                    StageMs = fulcrum == null || steps == 0 ? null : Array.ConvertAll(stages[f], t => t / steps),
                    WallMedianMs = Percentile(wallMs[f], 0.5),
                    BytesPerStep = steps > 0 ? (double)allocated[f] / steps : 0,
                    ProcessBytesPerStep = steps > 0 ? (double)processAllocated[f] / steps : 0,
                    Drift = drift[f],
                    Sink = sink[f],
                    MaxGroundPenetration = maxPenetration[f],
                    EndSpeed = endSpeed[f],
                    Finite = finite,
                };
            }
            return results;
        }

        // Reads every pose after a step: the deepest corner below the ground, the summed distance
        // the boxes moved since the last read (previous is updated), and whether all are finite.
        static void ReadPoses(IPeerEngine engine, PeerScene scene, Vector3[] previous, float groundTop, ref bool finite,
            out double penetration, out double moved)
        {
            penetration = 0;
            moved = 0;
            for (int i = 0; i < scene.Boxes.Count; i++)
            {
                engine.ReadPose(i, out Vector3 p, out Quaternion q);
                if (!(float.IsFinite(p.X) && float.IsFinite(p.Y) && float.IsFinite(p.Z))) { finite = false; continue; }
                penetration = Math.Max(penetration, groundTop - PeerBox.LowestY(p, q, scene.Boxes[i].HalfExtents));
                moved += Vector3.Distance(p, previous[i]);
                previous[i] = p;
            }
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
