using System.Numerics;
using Fulcrum;
using Fulcrum.Collision;
using NUnit.Framework;
using static Fulcrum.Tests.Solver.SolverTestScenes;

namespace Fulcrum.Tests.Solver
{
    public class ParallelTests
    {
        static Vector3[] Run(SolverType solver, int threads)
        {
            WorldSettings s = Settings(solver);
            s.Threads = threads;
            s.EnableSleeping = false;
            var w = new World(s);
            Ground(w);
            Pyramid(w, 20);
            // Something moving: a swinging chain dropped onto the pyramid.
            BodyHandle prev = BodyHandle.None;
            Vector3 anchor = new Vector3(-3, 14, 0);
            for (int i = 0; i < 6; i++)
            {
                BodyHandle link = Box(w, new Vector3(-3 + 0.5f + i, 14, 0), new Vector3(0.5f, 0.1f, 0.1f), 1f);
                w.CreateJoint(JointDef.Ball(prev, link, anchor, new Vector3(-0.5f, 0, 0)));
                prev = link;
                anchor = new Vector3(0.5f, 0, 0);
            }
            for (int n = 0; n < 90; n++) w.Step(1f / 60f);
            if (threads > 1) Assert.That(w.SolverPoolForTests!.SplitCalls, Is.GreaterThan(100), "the colour batches were split between threads");
            var result = new Vector3[w.BodyCount];
            var handles = new BodyHandle[w.BodyCount];
            w.GetBodies(handles);
            for (int i = 0; i < handles.Length; i++) result[i] = w.GetBody(handles[i]).Position;
            return result;
        }

        // A falling pile: hundreds of bodies side by side at each level of the shock-propagation
        // sweep, which splits a level's upper bodies between threads.
        static Vector3[] RunPile(SolverType solver, int threads, out int widestLevel, out System.Collections.Generic.List<string> events)
        {
            WorldSettings s = Settings(solver);
            s.Threads = threads;
            s.EnableSleeping = false;
            var w = new World(s);
            Ground(w);
            var random = new System.Random(7);
            for (int layer = 0; layer < 3; layer++)
                for (int i = 0; i < 12; i++)
                    for (int k = 0; k < 12; k++)
                    {
                        var axis = Vector3.Normalize(new Vector3((float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f, 0.3f));
                        Quaternion tilt = Quaternion.CreateFromAxisAngle(axis, 0.3f * (float)random.NextDouble());
                        // Every third box heavy: loads deep enough for the sweep to act on.
                        float mass = (i + k + layer) % 3 == 0 ? 50f : 1f;
                        Box(w, new Vector3(-8 + 1.4f * i, 0.6f + 1.3f * layer, -8 + 1.4f * k), new Vector3(0.5f), mass, tilt);
                    }
            events = new System.Collections.Generic.List<string>();
            for (int n = 0; n < 75; n++)
            {
                w.Step(1f / 60f);
                // The contact events (split between threads too), in order.
                foreach (ContactEvent e in w.ContactEvents)
                    events.Add($"{n} {e.Kind} {e.ShapeA.Index} {e.ShapeB.Index} {e.PointCount} {e.NormalImpulse:R} {e.Point}");
            }
            widestLevel = w.SolverContextForTests.ShockForTests.WidestLevel;
            var result = new Vector3[w.BodyCount];
            var handles = new BodyHandle[w.BodyCount];
            w.GetBodies(handles);
            for (int i = 0; i < handles.Length; i++) result[i] = w.GetBody(handles[i]).Position;
            return result;
        }

        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void A_falling_pile_on_four_threads_matches_one_thread_bit_for_bit(SolverType solver)
        {
            Vector3[] one = RunPile(solver, 1, out _, out var oneEvents);
            Vector3[] four = RunPile(solver, 4, out int widest, out var fourEvents);
            Assert.That(oneEvents.Count, Is.GreaterThan(10000), "contact events to compare");
            Assert.That(fourEvents, Is.EqualTo(oneEvents), "the contact events, in order");
            // The sweep's minimum share is 64 upper bodies: a level this wide is split.
            Assert.That(widest, Is.GreaterThan(128), "a level of the sweep wide enough to split");
            Assert.That(four.Length, Is.EqualTo(one.Length));
            for (int i = 0; i < one.Length; i++) Assert.That(four[i], Is.EqualTo(one[i]), $"body {i}");
        }

        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void One_thread_and_four_threads_give_bit_identical_results(SolverType solver)
        {
            Vector3[] one = Run(solver, 1);
            Vector3[] four = Run(solver, 4);
            Assert.That(four.Length, Is.EqualTo(one.Length));
            for (int i = 0; i < one.Length; i++) Assert.That(four[i], Is.EqualTo(one[i]), $"body {i}");
        }
    }
}
