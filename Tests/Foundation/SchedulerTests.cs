using System;
using System.Numerics;
using Fulcrum.SoftBodies;
using Fulcrum.Tests.SoftBodies;
using NUnit.Framework;
using static Fulcrum.Tests.Solver.SolverTestScenes;

namespace Fulcrum.Tests.Foundation
{
    /// <summary>
    /// World.Scheduler: a host's parallel-for runs the step's parallel work (solver, narrow
    /// phase, soft bodies) instead of the world's own pool, with the results of one thread.
    /// </summary>
    public class SchedulerTests
    {
        // A host scheduler on the caller's thread that splits finer than asked and runs the
        // chunks last first: any dependence of the results on chunking or order shows.
        sealed class ReversingScheduler : IParallelScheduler
        {
            public int Calls, SoftCalls;
            public int ThreadCount => 4;

            public void For(IParallelJob job, int start, int end, int minChunk)
            {
                Calls++;
                if (minChunk == 64) SoftCalls++; // the soft bodies' chunk (SoftBody.MinChunk); no rigid pass asks for 64
                int chunk = Math.Max(1, minChunk / 8);
                int chunks = (end - start + chunk - 1) / chunk;
                for (int c = chunks - 1; c >= 0; c--)
                {
                    int s = start + c * chunk;
                    job.Execute(s, Math.Min(end, s + chunk));
                }
            }
        }

        static Vector3[] Positions(World w)
        {
            var handles = new BodyHandle[w.BodyCount];
            w.GetBodies(handles);
            var result = new Vector3[handles.Length];
            for (int i = 0; i < handles.Length; i++) result[i] = w.GetBody(handles[i]).Position;
            return result;
        }

        static World Pile(int threads, IParallelScheduler? scheduler)
        {
            WorldSettings s = Settings(SolverType.Tgs);
            s.Threads = threads;
            s.EnableSleeping = false;
            var w = new World(s) { Scheduler = scheduler };
            Ground(w);
            Pyramid(w, 12);
            for (int i = 0; i < 40; i++) Sphere(w, new Vector3(-4 + 0.45f * (i % 20), 12 + i / 20, 0.3f), 0.2f, 1f);
            return w;
        }

        [Test]
        public void A_host_scheduler_runs_the_rigid_step_with_one_threads_results()
        {
            World one = Pile(1, null);
            var host = new ReversingScheduler();
            World four = Pile(4, host);
            for (int n = 0; n < 90; n++)
            {
                one.Step(1f / 60f);
                four.Step(1f / 60f);
            }
            Assert.That(host.Calls, Is.GreaterThan(90 * 10), "the solver's batches went through the host scheduler");
            Assert.That(four.ParallelNarrowPhaseSteps, Is.GreaterThan(0), "the narrow phase ran on it too");
            Assert.That(four.SolverPoolForTests, Is.Null, "the world started no threads of its own");
            Assert.That(Positions(four), Is.EqualTo(Positions(one)));
        }

        static World Jelly(int threads, IParallelScheduler? scheduler, out SoftBodyHandle jelly)
        {
            World world = SoftBodyScenes.WorldWithGround();
            WorldSettings s = world.Settings;
            s.Threads = threads;
            world.Settings = s;
            world.Scheduler = scheduler;
            var material = new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 5e4f, 0.45f, 1000f);
            var def = SoftBodyDef.Of(SoftMesh.Box(new Vector3(0.5f, 0.2f, 0.5f), 5, 2, 5), material, new Vector3(0, 0.105f, 0));
            def.Probes = new[] { new Vector3(0, 0.1f, 0) };
            jelly = world.CreateSoftBody(def);
            BodyHandle box = world.CreateBody(BodyDef.Dynamic(new Vector3(0, 0.32f, 0)));
            world.AddShape(box, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.1f))));
            return world;
        }

        [Test]
        public void A_host_scheduler_runs_the_soft_bodies_with_one_threads_results()
        {
            World one = Jelly(1, null, out SoftBodyHandle jellyOne);
            var host = new ReversingScheduler();
            World four = Jelly(4, host, out SoftBodyHandle jellyFour);
            for (int n = 0; n < 30; n++)
            {
                one.Step(SoftBodyScenes.Dt);
                four.Step(SoftBodyScenes.Dt);
            }
            Assert.That(host.SoftCalls, Is.GreaterThan(30), "the soft bodies' colours went through the host scheduler");
            Assert.That(four.GetSoftBody(jellyFour).GetProbe(0), Is.EqualTo(one.GetSoftBody(jellyOne).GetProbe(0)));
            Assert.That(Positions(four), Is.EqualTo(Positions(one)));
        }

        [Test]
        public void The_scheduler_is_the_worlds_own_by_default_and_can_be_set_and_cleared()
        {
            var w = new World(WorldSettings.Default);
            Assert.That(w.Scheduler, Is.Null);
            var host = new ReversingScheduler();
            w.Scheduler = host;
            Assert.That(w.Scheduler, Is.SameAs(host));
            w.Scheduler = null;
            Assert.That(w.Scheduler, Is.Null);
        }
    }
}
