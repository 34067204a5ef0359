using System.Numerics;
using Fulcrum.Components;
using NUnit.Framework;

namespace Fulcrum.Tests.Components
{
    /// <summary>
    /// <see cref="Rigidbody.constraints"/> maps to the core's <see cref="AxisLocks"/> through the
    /// public body API: the solver enforces them, no snapping around the step.
    /// </summary>
    public class RigidbodyConstraintsTests
    {
        const float Dt = 1f / 50f;

        static PhysicsScene Scene(bool gravity)
        {
            WorldSettings s = WorldSettings.Default;
            if (!gravity) s.Gravity = Vector3.Zero;
            return new PhysicsScene(s, Dt);
        }

        static Rigidbody Cube(PhysicsScene scene, Vector3 at, float mass = 2f)
        {
            Entity e = scene.CreateEntity("Cube", at);
            var rb = e.AddComponent<Rigidbody>();
            rb.mass = mass;
            rb.angularDamping = 0f;
            e.AddComponent<BoxCollider>().size = Vector3.One;
            return rb;
        }

        [TestCase(RigidbodyConstraints.FreezePositionX, AxisLocks.LinearX)]
        [TestCase(RigidbodyConstraints.FreezePositionY, AxisLocks.LinearY)]
        [TestCase(RigidbodyConstraints.FreezePositionZ, AxisLocks.LinearZ)]
        [TestCase(RigidbodyConstraints.FreezeRotationX, AxisLocks.AngularX)]
        [TestCase(RigidbodyConstraints.FreezeRotationY, AxisLocks.AngularY)]
        [TestCase(RigidbodyConstraints.FreezeRotationZ, AxisLocks.AngularZ)]
        [TestCase(RigidbodyConstraints.FreezeAll, AxisLocks.All)]
        public void Each_constraint_flag_is_the_core_lock_of_the_same_axis(RigidbodyConstraints flag, AxisLocks locks)
        {
            PhysicsScene scene = Scene(gravity: false);
            Rigidbody before = Cube(scene, Vector3.Zero);
            before.constraints = flag;   // set on a live body
            scene.Tick(Dt);
            Assert.That(scene.world.GetBody(before.body).Locks, Is.EqualTo(locks));
            before.constraints = RigidbodyConstraints.None;
            Assert.That(scene.world.GetBody(before.body).Locks, Is.EqualTo(AxisLocks.None));

            // Set while inactive: the body is created with the locks (BodyDef.Locks).
            Rigidbody later = Cube(scene, new Vector3(5, 0, 0));
            later.entity.SetActive(false);
            later.constraints = flag;
            later.entity.SetActive(true);
            Assert.That(scene.world.GetBody(later.body).Locks, Is.EqualTo(locks));
        }

        // Frozen in y and in rotation, a 2 kg cube is struck 0.3 m off its centre by a 1 kg cube
        // sliding in x, without friction: the solver knows the cube cannot turn, so the whole
        // blow goes into its translation (a common speed of 5/3 m/s after an inelastic hit at
        // 5 m/s) and its y and rotation stay exactly.
        [Test]
        public void A_cube_frozen_in_y_and_tilt_takes_an_off_centre_blow_as_the_solver_sees_it()
        {
            PhysicsScene scene = Scene(gravity: false);
            Rigidbody target = Cube(scene, Vector3.Zero);
            target.constraints = RigidbodyConstraints.FreezePositionY | RigidbodyConstraints.FreezeRotation;
            Rigidbody bullet = Cube(scene, new Vector3(-3, 0.3f, 0), mass: 1f);
            bullet.constraints = RigidbodyConstraints.FreezeRotation;
            bullet.linearVelocity = new Vector3(5, 0, 0);
            var zero = new PhysicsMaterial { dynamicFriction = 0, staticFriction = 0, frictionCombine = CombineMode.Minimum };
            target.GetComponent<BoxCollider>()!.sharedMaterial = zero;
            bullet.GetComponent<BoxCollider>()!.sharedMaterial = zero;
            for (int k = 0; k < 60; k++) scene.Tick(Dt);
            Assert.That(target.position.Y, Is.EqualTo(0f));
            Assert.That(target.rotation, Is.EqualTo(Quaternion.Identity));
            Assert.That(target.linearVelocity.X, Is.EqualTo(5f / 3f).Within(0.02f));
            Assert.That(2f * target.linearVelocity.X + bullet.linearVelocity.X, Is.EqualTo(5f).Within(1e-3f));
        }
    }
}
