using System;
using System.Diagnostics;
using System.IO;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;

namespace Fulcrum.Benchmarks
{
    /// <summary>
    /// Collision cost per step (broad + narrow phase) of box piles and a mixed-shape pile on one
    /// thread and on all cores, the bytes a step allocates, and pair finding by the dynamic tree
    /// against brute force and sweep-and-prune on piles of growing size.
    /// </summary>
    public sealed class BroadPhaseBenchmark : IBenchmark
    {
        public string Name => "broadphase";

        public string Description => "collision ms/step for 1k/4k/16k box piles and a mixed pile, 1 thread and all cores; tree vs brute force vs SAP pair finding";

        public void Run(TextWriter output, bool quick)
        {
            int cores = Environment.ProcessorCount;
            output.WriteLine("Per step, median over the measured steps (best step in brackets); the machine may be shared.");
            output.WriteLine($"1 thread: WorldSettings.Threads = 1; all cores: Threads = {cores} (the narrow phase's pair functions");
            output.WriteLine("and the solver run on the worker pool; the results are bit-identical). Bytes/step: the stepping thread.");
            output.WriteLine();
            output.WriteLine("Manifold reuse off: WorldSettings.ManifoldReuseDistance = 0 (every touching pair runs its pair function every step).");
            output.WriteLine();
            output.WriteLine($"| pile | bodies | touching points (manifolds) | broad ms, 1 thread | narrow ms, 1 thread | collide ms, 1 thread | narrow ms, 1 thread, reuse off | broad ms, {cores} threads | narrow ms, {cores} threads | collide ms, {cores} threads | bytes/step (1 / {cores}) |");
            output.WriteLine("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
            int[] sizes = quick ? new[] { 1000, 4000 } : new[] { 1000, 4000, 16000 };
            foreach (int n in sizes) PileRow(output, $"boxes {n / 1000}k", n, mixed: false, steps: quick ? 20 : 40);
            PileRow(output, "mixed 4k", 4000, mixed: true, steps: quick ? 20 : 40);
            output.WriteLine();

            output.WriteLine("Pair finding on a pile (all overlapping AABB pairs, best of 3):");
            output.WriteLine();
            output.WriteLine("tree: build by insertion + query every box; tree update: 10 % of the boxes moved, re-inserted and");
            output.WriteLine("queried (what the broad phase does in a step); SAP: sort on x + sweep; brute force: all pairs.");
            output.WriteLine();
            output.WriteLine("| bodies | pairs | tree ms | tree ms / (n log2 n) x 1e6 | tree update ms | SAP ms | brute force ms |");
            output.WriteLine("|---:|---:|---:|---:|---:|---:|---:|");
            int[] counts = quick ? new[] { 1250, 2500, 5000, 10000 } : new[] { 1250, 2500, 5000, 10000, 20000 };
            foreach (int n in counts) PairRow(output, n, brute: n <= 10000);
        }

        static void PileRow(TextWriter output, string name, int count, bool mixed, int steps)
        {
            var one = Measure(count, mixed, steps, 1);
            var fresh = Measure(count, mixed, steps, 1, reuse: false);
            var all = Measure(count, mixed, steps, Environment.ProcessorCount);
            if (all.Contacts != one.Contacts)
                throw new InvalidOperationException($"{name}: {one.Contacts} touching points on 1 thread, {all.Contacts} on {Environment.ProcessorCount}");
            output.WriteLine($"| {name} | {count} | {one.Contacts} ({one.Manifolds}) | {one.Broad} | {one.Narrow} | {one.Both} | {fresh.Narrow} | {all.Broad} | {all.Narrow} | {all.Both} | {one.Bytes} / {all.Bytes} |");
        }

        static (string Broad, string Narrow, string Both, long Bytes, int Contacts, int Manifolds) Measure(int count, bool mixed, int steps, int threads, bool reuse = true)
        {
            World w = Pile(count, mixed, 1, threads);
            if (!reuse)
            {
                WorldSettings s = w.Settings;
                s.ManifoldReuseDistance = 0;
                w.Settings = s;
            }
            for (int i = 0; i < 20; i++) w.Step(1 / 60f);
            var broad = new double[steps];
            var narrow = new double[steps];
            var both = new double[steps];
            long bytes = 0;
            for (int i = 0; i < steps; i++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                w.Step(1 / 60f);
                bytes += GC.GetAllocatedBytesForCurrentThread() - before;
                broad[i] = w.LastStepProfile.BroadPhase;
                narrow[i] = w.LastStepProfile.NarrowPhase;
                both[i] = broad[i] + narrow[i];
            }
            return (Stat(broad), Stat(narrow), Stat(both), bytes / steps, w.ContactCount, w.Contacts.ManifoldCount);
        }

        static string Stat(double[] values)
        {
            var sorted = (double[])values.Clone();
            Array.Sort(sorted);
            return $"{sorted[sorted.Length / 2]:F2} ({sorted[0]:F2})";
        }

        // A pile: columns of bodies 10 high on a static ground, each resting on the one below,
        // 5 cm from the neighbouring columns (inside the fat margin, outside the speculative
        // distance), drifting with small random velocities so the broad phase has work.
        internal static World Pile(int count, bool mixed, int seed, int threads = 1)
        {
            var s = WorldSettings.Default;
            s.Gravity = Vector3.Zero;
            s.EnableSleeping = false;
            s.Threads = threads;
            var w = new World(s);
            int layers = 10;
            int side = (int)MathF.Ceiling(MathF.Sqrt(count / (float)layers));
            const float spacing = 1.05f;
            w.AddShape(w.CreateBody(BodyDef.Static(new Vector3(side * spacing / 2, -0.5f, side * spacing / 2))), ShapeDef.Of(ShapeGeometry.Box(new Vector3(side * spacing, 0.5f, side * spacing))));
            var hull = ConvexHull.Create(new[]
            {
                new Vector3(-0.5f, -0.5f, -0.5f), new Vector3(0.5f, -0.5f, -0.5f), new Vector3(0, -0.5f, 0.5f),
                new Vector3(-0.3f, 0.5f, 0), new Vector3(0.3f, 0.5f, 0.1f), new Vector3(0, 0.5f, -0.4f),
            });
            var r = new Random(seed);
            int made = 0;
            for (int y = 0; y < layers && made < count; y++)
                for (int x = 0; x < side && made < count; x++)
                    for (int z = 0; z < side && made < count; z++, made++)
                    {
                        BodyDef d = BodyDef.Dynamic(new Vector3(x * spacing, 0.495f + 0.99f * y, z * spacing));
                        d.LinearVelocity = new Vector3((float)r.NextDouble() - 0.5f, (float)r.NextDouble() - 0.5f, (float)r.NextDouble() - 0.5f) * 0.02f;
                        BodyHandle b = w.CreateBody(d);
                        ShapeGeometry g = !mixed ? ShapeGeometry.Box(new Vector3(0.5f)) : (made % 4) switch
                        {
                            0 => ShapeGeometry.Box(new Vector3(0.5f)),
                            1 => ShapeGeometry.Sphere(0.5f),
                            2 => ShapeGeometry.Capsule(0.3f, 0.2f),
                            _ => ShapeGeometry.ConvexHull(hull),
                        };
                        w.AddShape(b, ShapeDef.Of(g));
                    }
            return w;
        }

        static void PairRow(TextWriter output, int n, bool brute)
        {
            World w = Pile(n, false, 2);
            var boxes = new Aabb[n];
            int k = 0;
            ShapeStorage s = w.Shapes;
            for (int i = 0; i < s.ActiveCount && k < n; i++)
            {
                int slot = s.Active[i];
                if (w.Bodies.Type[s.Body[slot]] == BodyType.Static) continue;
                boxes[k++] = s.WorldAabb[slot].Expanded(0.005f);
            }
            long pairsTree = 0, pairsSap = 0, pairsBrute = 0;
            double tree = Best(() => pairsTree = TreePairs(boxes));
            double sap = Best(() => pairsSap = SweepAndPrunePairs(boxes));
            double bf = brute ? Best(() => pairsBrute = BrutePairs(boxes)) : double.NaN;
            double update = TreeUpdate(boxes);
            if (pairsSap != pairsTree || (brute && pairsBrute != pairsTree))
                throw new InvalidOperationException($"pair counts disagree: tree {pairsTree}, SAP {pairsSap}, brute {pairsBrute}");
            double nlogn = n * Math.Log2(n);
            output.WriteLine($"| {n} | {pairsTree} | {tree:F2} | {tree / nlogn * 1e6:F2} | {update:F2} | {sap:F2} | {(brute ? bf.ToString("F1") : "-")} |");
        }

        static double Best(Action run)
        {
            double best = double.MaxValue;
            for (int i = 0; i < 3; i++)
            {
                var sw = Stopwatch.StartNew();
                run();
                best = Math.Min(best, sw.Elapsed.TotalMilliseconds);
            }
            return best;
        }

        struct Counter : ITreeOverlapCallback
        {
            public int Self;
            public long Pairs;
            public bool Visit(int proxyId, int userData)
            {
                if (userData > Self) Pairs++;
                return true;
            }
        }

        // Build the tree by insertion, then query every box.
        static long TreePairs(Aabb[] boxes)
        {
            var tree = new DynamicAabbTree();
            for (int i = 0; i < boxes.Length; i++) tree.CreateProxy(boxes[i], i);
            var c = new Counter();
            for (int i = 0; i < boxes.Length; i++)
            {
                c.Self = i;
                tree.Query(boxes[i], ref c);
            }
            return c.Pairs;
        }

        // A built tree; every step a tenth of the boxes move by a few centimetres and are
        // re-inserted and queried. Best of 3 rounds.
        static double TreeUpdate(Aabb[] boxes)
        {
            var tree = new DynamicAabbTree();
            var proxies = new int[boxes.Length];
            for (int i = 0; i < boxes.Length; i++) proxies[i] = tree.CreateProxy(boxes[i], i);
            var r = new Random(5);
            int moved = boxes.Length / 10;
            var which = new int[moved];
            var c = new Counter();
            return Best(() =>
            {
                for (int k = 0; k < moved; k++) which[k] = r.Next(boxes.Length);
                for (int k = 0; k < moved; k++)
                {
                    Vector3 shift = new Vector3((float)r.NextDouble() - 0.5f, 0, (float)r.NextDouble() - 0.5f) * 0.05f;
                    int i = which[k];
                    tree.MoveProxy(proxies[i], new Aabb(boxes[i].Min + shift, boxes[i].Max + shift));
                }
                for (int k = 0; k < moved; k++)
                {
                    c.Self = -1;
                    tree.Query(tree.FatAabb(proxies[which[k]]), ref c);
                }
            });
        }

        // Sort by min x, sweep keeping the boxes whose x range is still open.
        static long SweepAndPrunePairs(Aabb[] boxes)
        {
            int n = boxes.Length;
            var keys = new float[n];
            var order = new int[n];
            for (int i = 0; i < n; i++) { keys[i] = boxes[i].Min.X; order[i] = i; }
            Array.Sort(keys, order);
            long pairs = 0;
            for (int a = 0; a < n; a++)
            {
                ref Aabb ba = ref boxes[order[a]];
                for (int b = a + 1; b < n && keys[b] <= ba.Max.X; b++)
                    if (ba.Overlaps(boxes[order[b]])) pairs++;
            }
            return pairs;
        }

        static long BrutePairs(Aabb[] boxes)
        {
            long pairs = 0;
            for (int i = 0; i < boxes.Length; i++)
                for (int j = i + 1; j < boxes.Length; j++)
                    if (boxes[i].Overlaps(boxes[j])) pairs++;
            return pairs;
        }
    }
}
