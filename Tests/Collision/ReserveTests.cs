using System;
using System.Numerics;
using NUnit.Framework;

namespace Fulcrum.Tests.Collision
{
    /// <summary>World.Reserve: capacity up front, so a scene growing into it allocates nothing in Step.</summary>
    public class ReserveTests
    {
        static World Pile(int side, int layers, out int boxes, int threads = 1)
        {
            var s = WorldSettings.Default;
            s.EnableSleeping = false;
            s.Threads = threads;
            var w = new World(s);
            w.AddShape(w.CreateBody(BodyDef.Static(new Vector3(0, -0.5f, 0))), ShapeDef.Of(ShapeGeometry.Box(new Vector3(50, 0.5f, 50))));
            var r = new Random(12345);
            float start = -0.75f * (side - 1);
            boxes = 0;
            for (int l = 0; l < layers; l++)
                for (int i = 0; i < side; i++)
                    for (int k = 0; k < side; k++)
                    {
                        var axis = Vector3.Normalize(new Vector3((float)r.NextDouble() - 0.5f, (float)r.NextDouble() - 0.5f, (float)r.NextDouble() - 0.5f) + new Vector3(1e-3f));
                        BodyDef d = BodyDef.Dynamic(new Vector3(start + 1.5f * i, 1f + 1.5f * l, start + 1.5f * k));
                        d.Rotation = Quaternion.CreateFromAxisAngle(axis, 0.3f * (float)r.NextDouble());
                        d.Mass = 1;
                        w.AddShape(w.CreateBody(d), ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
                        boxes++;
                    }
            return w;
        }

        // Bytes allocated by the whole process so far. Unity's profile (netstandard2.1) has no
        // such count: there the process-wide check reads 0 and only the thread's count is tested.
        static long ProcessBytes()
        {
#if NET
            return GC.GetTotalAllocatedBytes(true);
#else
            return 0;
#endif
        }

        // Bytes the stepping thread allocated over 240 steps of the collapse; processBytes: the
        // whole process over the same steps (worker threads too).
        static long Collapse(World w, out int growingSteps, out long processBytes)
        {
            // The first step of a process initialises statics once; measure from the second.
            w.Step(1 / 60f);
            long total = 0;
            growingSteps = 0;
            processBytes = -ProcessBytes();
            for (int n = 0; n < 240; n++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                w.Step(1 / 60f);
                long a = GC.GetAllocatedBytesForCurrentThread() - before;
                total += a;
                if (a > 0) growingSteps++;
            }
            processBytes += ProcessBytes();
            return total;
        }

        [TestCase(1)]
        [TestCase(2)]
        public void A_collapsing_pile_with_reserved_capacity_allocates_nothing_while_its_contacts_multiply(int threads)
        {
            World plain = Pile(6, 6, out int boxes, threads);
            long grown = Collapse(plain, out int growingSteps, out _);
            plain.StopThreads();
            // The tiered JIT may allocate a few bytes once on this thread while it promotes the
            // collapse's hot methods (seen: 160 B, only when other tests ran first; none with
            // DOTNET_TieredCompilation=0). A buffer that grows inside Step allocates in every
            // fresh world, so two reserved worlds collapse in turn and the smaller count is the
            // one that says whether Step grows anything.
            World reserved = null!;
            long bytes = long.MaxValue, processBytes = long.MaxValue;
            for (int attempt = 0; attempt < 2; attempt++)
            {
                System.Threading.Thread.Sleep(150); // let background tier-1 compiles finish
                reserved?.StopThreads();
                reserved = Pile(6, 6, out _, threads);
                reserved.Reserve(boxes + 1, 8 * boxes);
                bytes = Math.Min(bytes, Collapse(reserved, out _, out long all));
                processBytes = Math.Min(processBytes, all);
            }
            reserved.StopThreads();
            TestContext.Out.WriteLine($"{boxes} boxes, {threads} thread(s): {grown} B in {growingSteps} steps without Reserve, {bytes} B with ({processBytes} B in the whole process); {reserved.Contacts.ManifoldCount} manifolds at the end");
            Assert.That(grown, Is.GreaterThan(0), "without Reserve the buffers grow inside Step (what this test guards against)");
            Assert.That(bytes, Is.EqualTo(0));
            // The worker threads' share: the whole process over 240 steps, where the test
            // runner's own threads may allocate a little (seen: 0.7-1.8 KB); a buffer growing
            // per step on a worker would pass that (the stepping thread's growth this guards
            // against was 10 KB per step in a 2k-box pile, 1.1 MB here without Reserve).
            Assert.That(processBytes, Is.LessThan(64 * 1024));
            Assert.That(reserved.Contacts.ManifoldCount, Is.GreaterThan(boxes / 2), "the pile came to rest on itself");
        }

        [Test]
        public void Reserve_refuses_negative_counts_and_never_shrinks()
        {
            World w = Pile(2, 1, out _);
            Assert.That(() => w.Reserve(-1, 10), Throws.ArgumentException.With.Message.Contains("bodies"));
            Assert.That(() => w.Reserve(10, -1), Throws.ArgumentException.With.Message.Contains("contactPairs"));
            for (int n = 0; n < 30; n++) w.Step(1 / 60f);
            int manifolds = w.Contacts.ManifoldCount;
            w.Reserve(0, 0);
            w.Step(1 / 60f);
            Assert.That(w.Contacts.ManifoldCount, Is.EqualTo(manifolds));
        }
    }
}
