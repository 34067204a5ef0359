using System;
using System.IO;
using System.Numerics;
using Fulcrum;
using NUnit.Framework;
using static Fulcrum.Tests.Solver.SolverTestScenes;

namespace Fulcrum.Tests.Solver
{
    /// <summary>
    /// Axis locks (<see cref="AxisLocks"/>, issue 15 item 5): enforced inside the solver, so a
    /// locked coordinate does not change at all and contacts and joints compute their impulses
    /// for the mobility the body really has.
    /// </summary>
    public class AxisLockTests
    {
        const float Dt = 1f / 60f;
        const AxisLocks Planar = AxisLocks.LinearZ | AxisLocks.AngularX | AxisLocks.AngularY;

        static World NewWorld(SolverType solver, bool gravity = true)
        {
            WorldSettings s = Settings(solver);
            if (!gravity) s.Gravity = Vector3.Zero;
            s.EnableSleeping = false;
            return new World(s);
        }

        static void Run(World w, int steps)
        {
            for (int n = 0; n < steps; n++) w.Step(Dt);
        }

        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void A_box_with_LinearY_locked_stays_at_its_height_under_gravity_and_pushes(SolverType solver)
        {
            World w = NewWorld(solver);
            Ground(w);
            BodyHandle shelf = Box(w, new Vector3(0, 2, 0), new Vector3(1, 0.1f, 1), 5f);
            // Free to turn about y but not to tip: a plate held only at its centre is a balance
            // that any load off the centre tips over.
            w.SetAxisLocks(shelf, AxisLocks.LinearY | AxisLocks.AngularX | AxisLocks.AngularZ);
            // A 10 kg box falls onto it and rests there; pushes down and up and one sideways act
            // on it too.
            BodyHandle load = Box(w, new Vector3(0, 3, 0), new Vector3(0.25f), 10f);
            for (int n = 0; n < 120; n++)
            {
                BodyRef s = w.GetBody(shelf);
                if (n < 30) s.AddForce(new Vector3(0, -300, 0));
                else if (n < 60) s.AddForce(new Vector3(0, 500, 0));
                else if (n < 70) s.AddForce(new Vector3(30, 0, 0));
                w.Step(Dt);
                Assert.That(w.GetBody(shelf).Position.Y, Is.EqualTo(2f), $"step {n}");
                Assert.That(w.GetBody(shelf).LinearVelocity.Y, Is.EqualTo(0f), $"step {n}");
            }
            Assert.That(w.GetBody(shelf).Position.X, Is.GreaterThan(0.05f), "the sideways push moves it along the free x axis");
            Assert.That(w.GetBody(load).Position.Y, Is.GreaterThan(2.1f), $"the load rests on the shelf: load {w.GetBody(load).Position} shelf {w.GetBody(shelf).Position} {w.GetBody(shelf).Rotation}");
            Assert.That(w.GetBody(load).Position.Y, Is.LessThan(2.6f), "the load rests on the shelf");
        }

        // A 1 kg ball falls at 5 m/s onto a 2 kg box locked in y, without restitution. The box
        // is infinitely heavy along y, so the ball stops in the step of the impact and never
        // overlaps the box. (Snapping the box back after a solve that thought it free, as the
        // components did before, left the ball the common speed m v0 / (m + M) = 1.67 m/s: it
        // sank 10.8 mm into the box under TGS and 31.6 mm under PGS.)
        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void A_ball_dropped_on_a_box_locked_in_y_stops_in_the_impact_step(SolverType solver)
        {
            World w = NewWorld(solver, gravity: false);
            BodyHandle box = Box(w, Vector3.Zero, new Vector3(0.5f), 2f);
            w.SetAxisLocks(box, AxisLocks.LinearY);
            BodyHandle ball = Sphere(w, new Vector3(0, 1, 0), 0.25f, 1f);
            w.GetBody(ball).LinearVelocity = new Vector3(0, -5, 0);
            bool hit = false;
            for (int n = 0; n < 60; n++)
            {
                w.Step(Dt);
                BodyRef b = w.GetBody(ball);
                Assert.That(b.Position.Y - 0.25f - 0.5f, Is.GreaterThan(-1e-3f), $"step {n}: no overlap");
                if (!hit && b.LinearVelocity.Y > -4.9f)
                {
                    hit = true;
                    Assert.That(b.LinearVelocity.Y, Is.EqualTo(0f).Within(1e-3f), $"step {n}: stopped in the impact step");
                }
            }
            Assert.That(hit, Is.True);
            Assert.That(w.GetBody(box).Position, Is.EqualTo(Vector3.Zero));
        }

        // A 2D pile: boxes and spheres locked to the x-y plane (LinearZ, AngularX, AngularY)
        // fall on each other at staggered x and z, so contacts have normals and arms with z
        // parts (sphere on sphere, sphere on a box corner off the box's centre plane). Without
        // the locks the pile spreads in z and tilts; with them z and the tilt stay exactly.
        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void A_planar_pile_keeps_z_and_tilt_exactly(SolverType solver)
        {
            World w = NewWorld(solver);
            Ground(w);
            var bodies = new BodyHandle[18];
            var z = new float[bodies.Length];
            for (int i = 0; i < bodies.Length; i++)
            {
                z[i] = 0.3f + 0.35f * ((i * 7) % 3 - 1);
                var at = new Vector3(0.37f * ((i * 5) % 4) - 0.5f, 0.6f + 0.9f * i, z[i]);
                BodyDef d = BodyDef.Dynamic(at);
                d.Rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.4f * i);
                d.AngularVelocity = new Vector3(1, -2, 0.5f * (i % 3)); // x, y parts removed by the locks
                d.LinearVelocity = new Vector3(0, 0, 0.5f);              // so is the z part
                d.Locks = Planar;
                BodyHandle b = w.CreateBody(d);
                ShapeGeometry g = i % 3 == 2 ? ShapeGeometry.Sphere(0.3f) : ShapeGeometry.Box(new Vector3(0.4f, 0.2f, 0.3f + 0.05f * (i % 2)));
                w.AddShape(b, ShapeDef.Of(g));
                bodies[i] = b;
            }
            float turned = 0;
            for (int n = 0; n < 300; n++)
            {
                w.Step(Dt);
                for (int i = 0; i < bodies.Length; i++)
                {
                    BodyRef b = w.GetBody(bodies[i]);
                    Quaternion q = b.Rotation;
                    if (b.Position.Z != z[i] || q.X != 0 || q.Y != 0)
                        Assert.Fail($"step {n}, body {i}: z {b.Position.Z:R} (was {z[i]:R}), rotation {q}");
                    Assert.That(b.LinearVelocity.Z, Is.EqualTo(0f));
                    Assert.That(b.AngularVelocity.X, Is.EqualTo(0f));
                    Assert.That(b.AngularVelocity.Y, Is.EqualTo(0f));
                }
            }
            for (int i = 0; i < bodies.Length; i++)
                turned = MathF.Max(turned, MathF.Abs(Rotation(w, bodies[i]) - 0.4f * i));
            Assert.That(turned, Is.GreaterThan(0.1f), "bodies turned about z in the pile: the test is not vacuous");
            Assert.That(w.GetBody(bodies[^1]).Position.Y, Is.LessThan(0.6f + 0.9f * 17 - 5f), "the pile fell");
        }

        static float Rotation(World w, BodyHandle b) => Mathematics.Rotation.ToRotationVector(w.GetBody(b).Rotation).Z;

        // A 2 kg box with all rotation locked is struck 0.4 m off its centre by a 1 kg sphere at
        // 5 m/s, without friction or restitution. A body of infinite inertia takes the impulse
        // at its centre: both end at the common speed m v0 / (m + M) = 5/3 m/s and the box does
        // not turn. (Free, the box would turn and the point would see 1/m_eff = 1/2 + 0.4^2/I = 0.98.)
        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void A_box_with_all_rotation_locked_struck_off_centre_takes_the_momentum_of_infinite_inertia(SolverType solver)
        {
            World w = NewWorld(solver, gravity: false);
            BodyHandle box = Box(w, Vector3.Zero, new Vector3(0.5f), 2f, friction: 0f);
            w.GetBody(box).Locks = AxisLocks.Angular;
            BodyHandle ball = Sphere(w, new Vector3(-2, 0.4f, 0), 0.25f, 1f, friction: 0f);
            w.GetBody(ball).LinearVelocity = new Vector3(5, 0, 0);
            Run(w, 60);
            BodyRef b = w.GetBody(box), s = w.GetBody(ball);
            Assert.That(b.AngularVelocity, Is.EqualTo(Vector3.Zero));
            Assert.That(b.Rotation, Is.EqualTo(Quaternion.Identity));
            Assert.That(b.LinearVelocity.X, Is.EqualTo(5f / 3f).Within(0.01f));
            Assert.That(b.LinearVelocity.Y, Is.EqualTo(0f).Within(1e-5f), "the impulse is along the normal only");
            Assert.That(s.LinearVelocity.X, Is.EqualTo(5f / 3f).Within(0.02f));
            Assert.That(2f * b.LinearVelocity.X + s.LinearVelocity.X, Is.EqualTo(5f).Within(1e-3f), "momentum");
        }

        // A tilted 2 kg box locked along y is hit by a 1 kg sphere coming down obliquely, with
        // friction: the lock takes up momentum along y only; along x and z the pair keeps it.
        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void A_locked_body_in_contact_with_a_free_body_conserves_momentum_along_the_free_axes(SolverType solver)
        {
            World w = NewWorld(solver, gravity: false);
            BodyHandle box = Box(w, Vector3.Zero, new Vector3(0.5f), 2f, Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.35f), friction: 0.8f);
            w.SetAxisLocks(box, AxisLocks.LinearY | AxisLocks.AngularX);
            var v0 = new Vector3(3, -2, 1);
            BodyHandle ball = Sphere(w, new Vector3(-0.7f, 1.4f, -0.2f) - 0.3f * v0, 0.3f, 1f, friction: 0.8f);
            w.GetBody(ball).LinearVelocity = v0;
            Run(w, 60);
            BodyRef b = w.GetBody(box), s = w.GetBody(ball);
            Assert.That((s.LinearVelocity - v0).Length(), Is.GreaterThan(0.5f), "they collided");
            Vector3 p = 2f * b.LinearVelocity + s.LinearVelocity;
            Assert.That(p.X, Is.EqualTo(3f).Within(1e-4f));
            Assert.That(p.Z, Is.EqualTo(1f).Within(1e-4f));
            Assert.That(b.CenterOfMass.Y, Is.EqualTo(0f), $"local centre {b.LocalCenterOfMass}");
            Assert.That(b.AngularVelocity.X, Is.EqualTo(0f));
        }

        // A planar pendulum: a bar locked to the x-y plane hangs from the world by a ball joint
        // at its end. The joint's 3x3 effective mass is singular along z (nothing can move the
        // anchor there): the solver must solve the x-y rows, not give up on the joint.
        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void A_planar_pendulum_on_a_ball_joint_swings_in_its_plane_and_holds_its_pivot(SolverType solver)
        {
            World w = NewWorld(solver);
            BodyDef d = BodyDef.Dynamic(new Vector3(0.5f, 3, 0.2f));
            d.Locks = Planar;
            BodyHandle bar = w.CreateBody(d);
            w.AddShape(bar, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f, 0.05f, 0.1f))));
            var pivot = new Vector3(0, 3, 0.2f);
            w.CreateJoint(JointDef.Ball(BodyHandle.None, bar, pivot, new Vector3(-0.5f, 0, 0)));
            float lowest = 3;
            for (int n = 0; n < 120; n++)
            {
                w.Step(Dt);
                BodyRef b = w.GetBody(bar);
                Vector3 anchor = b.Position + Vector3.Transform(new Vector3(-0.5f, 0, 0), b.Rotation);
                Assert.That(Vector3.Distance(anchor, pivot), Is.LessThan(0.01f), $"step {n}: the pivot holds");
                Assert.That(b.Position.Z, Is.EqualTo(0.2f));
                Assert.That(b.Rotation.X, Is.EqualTo(0f));
                Assert.That(b.Rotation.Y, Is.EqualTo(0f));
                lowest = MathF.Min(lowest, b.Position.Y);
            }
            Assert.That(lowest, Is.LessThan(2.6f), "it swung down");
        }

        // A frame of a body locked in x and y, turning about z only, held by a fixed joint to a
        // free body: the rotation-lock rows are singular about x and y.
        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void A_fixed_joint_to_a_body_turning_only_about_z_carries_the_free_body(SolverType solver)
        {
            World w = NewWorld(solver, gravity: false);
            BodyDef d = BodyDef.Dynamic(Vector3.Zero);
            d.Locks = AxisLocks.Linear | AxisLocks.AngularX | AxisLocks.AngularY;
            d.AngularVelocity = new Vector3(0, 0, 2);
            BodyHandle hub = w.CreateBody(d);
            w.AddShape(hub, ShapeDef.Of(ShapeGeometry.Sphere(0.2f)));
            BodyHandle arm = Box(w, new Vector3(0.7f, 0, 0), new Vector3(0.3f, 0.05f, 0.05f), 1f);
            w.CreateJoint(JointDef.Fixed(hub, arm, new Vector3(0.7f, 0, 0), new Vector3(0, 0, 0)));
            Run(w, 60);
            BodyRef h = w.GetBody(hub), a = w.GetBody(arm);
            Assert.That(h.Position, Is.EqualTo(Vector3.Zero));
            Assert.That(h.AngularVelocity.Z, Is.GreaterThan(0.2f), "the hub still turns");
            Vector3 expected = Vector3.Transform(new Vector3(0.7f, 0, 0), h.Rotation);
            Assert.That(Vector3.Distance(a.Position, expected), Is.LessThan(0.02f), "the arm turns with the hub");
        }

        static (Vector3[] positions, Quaternion[] rotations, int groups) LockedTower(bool wide)
        {
            World w = NewWorld(SolverType.Tgs);
            w.SolverContextForTests.WideContacts = wide;
            Ground(w);
            var boxes = new BodyHandle[6];
            for (int i = 0; i < boxes.Length; i++)
            {
                BodyDef d = BodyDef.Dynamic(new Vector3(0.1f * i, 0.5f + 1.02f * i, 0));
                // Rotation locks only (the four-point face contacts may go wide), or translation
                // locks too (those contacts take the scalar path).
                d.Locks = i % 2 == 0 ? AxisLocks.Angular : AxisLocks.LinearX | AxisLocks.LinearZ | AxisLocks.AngularY;
                d.LinearVelocity = new Vector3(1.5f, 0, -1);
                d.AngularVelocity = new Vector3(0, 2, 0);
                BodyHandle b = w.CreateBody(d);
                w.AddShape(b, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
                boxes[i] = b;
            }
            var p = new Vector3[boxes.Length];
            var q = new Quaternion[boxes.Length];
            int groups = 0;
            for (int n = 0; n < 90; n++)
            {
                w.Step(Dt);
                groups = Math.Max(groups, w.SolverContextForTests.WideGroupCount);
            }
            for (int i = 0; i < boxes.Length; i++)
            {
                p[i] = w.GetBody(boxes[i]).Position;
                q[i] = w.GetBody(boxes[i]).Rotation;
            }
            return (p, q, groups);
        }

        [Test]
        public void Wide_and_scalar_contact_paths_honour_the_locks_alike()
        {
            var (wide, wideTurn, groups) = LockedTower(true);
            var (scalar, scalarTurn, _) = LockedTower(false);
#if NET
            // The SIMD contact path exists only in the .NET build (Unity's runs every contact scalar).
            if (System.Numerics.Vector.IsHardwareAccelerated) Assert.That(groups, Is.GreaterThan(0), "some contacts went wide");
#endif
            for (int i = 0; i < wide.Length; i++)
            {
                Assert.That(Vector3.Distance(wide[i], scalar[i]), Is.LessThan(2e-3f), $"box {i}");
                if (i % 2 == 0)
                {
                    Assert.That(wideTurn[i], Is.EqualTo(Quaternion.Identity), $"box {i} cannot turn");
                    Assert.That(scalarTurn[i], Is.EqualTo(Quaternion.Identity), $"box {i} cannot turn");
                }
                else
                {
                    Assert.That(wide[i].X, Is.EqualTo(0.1f * i), $"box {i} x");
                    Assert.That(wide[i].Z, Is.EqualTo(0f), $"box {i} z");
                    Assert.That(scalar[i].X, Is.EqualTo(0.1f * i), $"box {i} x");
                }
            }
            Assert.That(wide[0].X, Is.GreaterThan(0.05f), "the bottom box slid along x");
        }

        [Test]
        public void Locks_are_validated_all_or_nothing_and_mask_the_velocity_when_set()
        {
            World w = NewWorld(SolverType.Tgs, gravity: false);
            BodyDef bad = BodyDef.Dynamic(Vector3.Zero);
            bad.Locks = (AxisLocks)64;
            Assert.That(() => w.CreateBody(bad), Throws.ArgumentException.With.Message.Contains("body.Locks"));
            Assert.That(w.BodyCount, Is.EqualTo(0));

            BodyHandle box = Box(w, Vector3.Zero, new Vector3(0.5f, 0.2f, 0.3f), 1f);
            BodyRef b = w.GetBody(box);
            b.LinearVelocity = new Vector3(1, 2, 3);
            b.AngularVelocity = new Vector3(4, 5, 6);
            Assert.That(() => w.SetAxisLocks(box, AxisLocks.LinearX | (AxisLocks)128), Throws.ArgumentException);
            Assert.That(w.GetAxisLocks(box), Is.EqualTo(AxisLocks.None));
            Assert.That(b.LinearVelocity, Is.EqualTo(new Vector3(1, 2, 3)));

            b.Locks = AxisLocks.LinearY | AxisLocks.AngularX | AxisLocks.AngularZ;
            Assert.That(b.Locks, Is.EqualTo(AxisLocks.LinearY | AxisLocks.AngularX | AxisLocks.AngularZ));
            Assert.That(b.LinearVelocity, Is.EqualTo(new Vector3(1, 0, 3)));
            Assert.That(b.AngularVelocity, Is.EqualTo(new Vector3(0, 5, 0)));
            // The world inverse inertia is projected: only the y row and column are left.
            Mathematics.Mat3 ii = b.InverseInertiaWorld;
            Assert.That(ii.R0, Is.EqualTo(Vector3.Zero));
            Assert.That(ii.R2, Is.EqualTo(Vector3.Zero));
            Assert.That(ii.C1.Y, Is.GreaterThan(0f));
        }

        [Test]
        public void Locks_survive_save_and_restore_and_the_run_goes_on_bit_identically()
        {
            World w = NewWorld(SolverType.Tgs);
            Ground(w);
            BodyHandle shelf = Box(w, new Vector3(0, 1, 0), new Vector3(1, 0.1f, 1), 5f);
            w.SetAxisLocks(shelf, AxisLocks.LinearY | AxisLocks.Angular);
            BodyHandle plate = Box(w, new Vector3(2.5f, 1, 0), new Vector3(0.5f, 0.1f, 0.3f), 1f, Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.3f));
            w.SetAxisLocks(plate, Planar);
            BodyHandle load = Box(w, new Vector3(0.2f, 2, 0), new Vector3(0.25f), 3f);
            Run(w, 20);
            var saved = new MemoryStream();
            w.SaveState(saved);
            Run(w, 40);
            Vector3[] expected = { w.GetBody(shelf).Position, w.GetBody(plate).Position, w.GetBody(load).Position };
            Quaternion plateTurn = w.GetBody(plate).Rotation;

            w.SetAxisLocks(shelf, AxisLocks.None);
            w.SetAxisLocks(plate, AxisLocks.LinearX);
            w.RestoreState(new MemoryStream(saved.ToArray()));
            Assert.That(w.GetAxisLocks(shelf), Is.EqualTo(AxisLocks.LinearY | AxisLocks.Angular));
            Assert.That(w.GetAxisLocks(plate), Is.EqualTo(Planar));
            Run(w, 40);
            Assert.That(w.GetBody(shelf).Position, Is.EqualTo(expected[0]));
            Assert.That(w.GetBody(plate).Position, Is.EqualTo(expected[1]));
            Assert.That(w.GetBody(load).Position, Is.EqualTo(expected[2]));
            Assert.That(w.GetBody(plate).Rotation, Is.EqualTo(plateTurn));
            Assert.That(w.GetBody(shelf).Position.Y, Is.EqualTo(1f));
        }

        [Test]
        public void Stepping_locked_bodies_in_contacts_and_joints_allocates_nothing()
        {
            World w = NewWorld(SolverType.Tgs);
            Ground(w);
            for (int i = 0; i < 12; i++)
            {
                BodyDef d = BodyDef.Dynamic(new Vector3(1.1f * (i % 4), 0.5f + 1.1f * (i / 4), 0));
                d.Locks = i % 2 == 0 ? Planar : AxisLocks.LinearX | AxisLocks.Angular;
                BodyHandle b = w.CreateBody(d);
                w.AddShape(b, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            }
            BodyDef p = BodyDef.Dynamic(new Vector3(-3, 3, 0));
            p.Locks = Planar;
            BodyHandle bar = w.CreateBody(p);
            w.AddShape(bar, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f, 0.05f, 0.1f))));
            w.CreateJoint(JointDef.Ball(BodyHandle.None, bar, new Vector3(-3.5f, 3, 0), new Vector3(-0.5f, 0, 0)));
            Run(w, 60);
            Assert.That(Foundation.AllocationTests.AllocatedOverSteps(w, 60), Is.EqualTo(0));
        }
    }
}
