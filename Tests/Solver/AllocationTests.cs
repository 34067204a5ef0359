using System;
using System.Numerics;
using Fulcrum;
using NUnit.Framework;
using static Fulcrum.Tests.Solver.SolverTestScenes;

namespace Fulcrum.Tests.Solver
{
    public class AllocationTests
    {
        [TestCase(SolverType.Tgs, false, 1)]
        [TestCase(SolverType.Tgs, true, 1)]
        [TestCase(SolverType.Pgs, true, 1)]
        [TestCase(SolverType.Tgs, true, 2)]
        [TestCase(SolverType.Pgs, true, 2)]
        public void A_warm_step_with_contacts_and_every_joint_kind_allocates_nothing(SolverType solver, bool block, int threads)
        {
            WorldSettings s = Settings(solver);
            s.BlockSolver = block;
            s.EnableSleeping = false;
            s.Threads = threads;
            var w = new World(s);
            Ground(w);
            Tower(w, 5);
            // On threads, enough contacts that the solver's passes are split between them: a
            // one-box-deep pyramid of 12 at the base, behind the rest.
            if (threads > 1)
                for (int row = 0; row < 12; row++)
                    for (int i = 0; i < 12 - row; i++)
                        Box(w, new Vector3(-0.5f * (11 - row) + i, 0.5f + row, -6), new Vector3(0.5f), 1f);
            BodyHandle a = Box(w, new Vector3(4, 3, 0), new Vector3(0.2f), 1f);
            BodyHandle b = Box(w, new Vector3(5, 3, 0), new Vector3(0.2f), 1f);
            BodyHandle c = Sphere(w, new Vector3(6, 3, 0), 0.2f, 1f);
            w.CreateJoint(JointDef.Ball(BodyHandle.None, a, new Vector3(4, 4, 0), new Vector3(0, 1, 0)));
            JointDef hinge = JointDef.Hinge(a, b, new Vector3(0.5f, 0, 0), new Vector3(-0.5f, 0, 0), Vector3.UnitZ, Vector3.UnitZ);
            hinge.LowerDeg = -45; hinge.UpperDeg = 45; hinge.MaxMotorTorque = 1; hinge.MotorSpeed = 1; hinge.StiffnessHz = 1;
            w.CreateJoint(hinge);
            w.CreateJoint(JointDef.Distance(b, c, Vector3.Zero, Vector3.Zero, 0.5f, 1.5f));
            JointDef slider = JointDef.Prismatic(BodyHandle.None, c, new Vector3(6, 3, 0), Vector3.Zero, Vector3.UnitY);
            slider.Lower = -1; slider.Upper = 1; slider.MaxMotorForce = 5;
            BodyHandle d = Box(w, new Vector3(8, 3, 0), new Vector3(0.2f), 1f);
            w.CreateJoint(slider);
            w.CreateJoint(JointDef.ConeTwist(BodyHandle.None, d, new Vector3(8, 4, 0), new Vector3(0, 1, 0), -Vector3.UnitY, -Vector3.UnitY, 30, 20));
            BodyHandle e = Box(w, new Vector3(10, 3, 0), new Vector3(0.2f), 1f);
            w.CreateJoint(JointDef.Fixed(BodyHandle.None, e, new Vector3(10, 3, 0), Vector3.Zero));
            // The fewest bytes of three windows after a warm-up (AllocationProbe): the tiered JIT
            // may allocate while it recompiles hot methods late on a loaded machine (3,096 bytes
            // in one measured window of a CI run beside a Unity build, none run alone); a real
            // per-step allocation shows in every window.
            long allocated = Fulcrum.Tests.Components.AllocationProbe.SteadyStateBytes(() => w.Step(1f / 60f));
            if (threads > 1) Assert.That(w.SolverPoolForTests!.SplitCalls, Is.GreaterThan(0), "the step's passes ran on the worker pool");
            w.StopThreads();
            Assert.That(allocated, Is.EqualTo(0));
        }
    }
}
