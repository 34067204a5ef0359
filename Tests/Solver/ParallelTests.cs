using System.Numerics;
using Fulcrum;
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
