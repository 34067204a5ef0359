using System;
using System.Numerics;
using Fulcrum.Components;
using NUnit.Framework;

namespace Fulcrum.Tests.Components
{
    public class RigidbodyTests
    {
        const float Dt = 1f / 64f; // exact in binary

        static PhysicsScene ZeroGravityScene()
        {
            WorldSettings s = WorldSettings.Default;
            s.Gravity = Vector3.Zero;
            return new PhysicsScene(s, Dt);
        }

        // A 2 kg ball of radius 0.5: I = 2/5 m r^2 = 0.2 kg m^2.
        static Rigidbody Ball(PhysicsScene scene, Vector3 at = default)
        {
            Entity e = scene.CreateEntity("Ball", at);
            var rb = e.AddComponent<Rigidbody>();
            rb.mass = 2f;
            rb.angularDamping = 0f;
            e.AddComponent<SphereCollider>().radius = 0.5f;
            return rb;
        }

        [TestCase(ForceMode.Force, 4f, 2f * Dt)]            // dv = F/m dt
        [TestCase(ForceMode.Acceleration, 3f, 3f * Dt)]     // dv = a dt
        [TestCase(ForceMode.Impulse, 4f, 2f)]               // dv = J/m
        [TestCase(ForceMode.VelocityChange, 5f, 5f)]        // dv = dv
        public void AddForce_modes_match_closed_forms(ForceMode mode, float amount, float expectedVelocity)
        {
            PhysicsScene scene = ZeroGravityScene();
            Rigidbody rb = Ball(scene);
            rb.AddForce(new Vector3(amount, 0, 0), mode);
            scene.Tick(Dt);
            Assert.That(rb.linearVelocity.X, Is.EqualTo(expectedVelocity).Within(1e-6f));
            Assert.That(rb.position.X, Is.EqualTo(expectedVelocity * Dt).Within(1e-7f), "semi-implicit Euler: x = v dt");
            scene.Tick(Dt);
            Assert.That(rb.linearVelocity.X, Is.EqualTo(expectedVelocity).Within(1e-6f), "a force lasts one step only");
        }

        [TestCase(ForceMode.Force, 1f, 5f * Dt)]            // dw = tau/I dt, I = 0.2
        [TestCase(ForceMode.Acceleration, 2f, 2f * Dt)]
        [TestCase(ForceMode.Impulse, 1f, 5f)]
        [TestCase(ForceMode.VelocityChange, 3f, 3f)]
        public void AddTorque_modes_match_closed_forms(ForceMode mode, float amount, float expectedSpin)
        {
            PhysicsScene scene = ZeroGravityScene();
            Rigidbody rb = Ball(scene);
            Assert.That(rb.inertiaTensor.C0.X, Is.EqualTo(0.2f).Within(1e-6f), "mass 2 kg scales the sphere's distribution");
            rb.AddTorque(new Vector3(0, 0, amount), mode);
            scene.Tick(Dt);
            Assert.That(rb.angularVelocity.Z, Is.EqualTo(expectedSpin).Within(1e-5f));
        }

        [Test]
        public void AddForceAtPosition_impulse_off_centre_gives_v_J_over_m_and_w_r_cross_J_over_I()
        {
            PhysicsScene scene = ZeroGravityScene();
            Rigidbody rb = Ball(scene);
            rb.AddForceAtPosition(new Vector3(0, 1, 0), new Vector3(1, 0, 0), ForceMode.Impulse);
            Assert.That(rb.linearVelocity.Y, Is.EqualTo(0.5f).Within(1e-6f));
            Assert.That(rb.angularVelocity.Z, Is.EqualTo(5f).Within(1e-5f));
            rb.AddRelativeForce(new Vector3(0, 0, 2), ForceMode.VelocityChange);
            Assert.That(rb.linearVelocity.Z, Is.EqualTo(2f).Within(1e-6f));
        }

        [Test]
        public void Gravity_applies_unless_useGravity_is_off()
        {
            var scene = new PhysicsScene(WorldSettings.Default, Dt);
            Rigidbody falling = Ball(scene);
            Rigidbody floating = Ball(scene, new Vector3(5, 0, 0));
            floating.useGravity = false;
            scene.Tick(Dt);
            Assert.That(falling.linearVelocity.Y, Is.EqualTo(-9.81f * Dt).Within(1e-6f));
            Assert.That(floating.linearVelocity.Y, Is.EqualTo(0f));
        }

        [Test]
        public void FreezePositionX_keeps_x_while_y_moves()
        {
            PhysicsScene scene = ZeroGravityScene();
            Rigidbody rb = Ball(scene);
            rb.constraints = RigidbodyConstraints.FreezePositionX;
            rb.linearVelocity = new Vector3(1, 1, 0);
            for (int k = 0; k < 8; k++) scene.Tick(Dt);
            Assert.That(rb.position.X, Is.EqualTo(0f));
            Assert.That(rb.position.Y, Is.EqualTo(8 * Dt).Within(1e-6f));
            Assert.That(rb.linearVelocity.X, Is.EqualTo(0f));
        }

        [Test]
        public void FreezeRotation_zeroes_the_inverse_inertia_so_torques_do_nothing()
        {
            PhysicsScene scene = ZeroGravityScene();
            Rigidbody rb = Ball(scene);
            rb.constraints = RigidbodyConstraints.FreezeRotation;
            rb.AddTorque(new Vector3(1, 2, 3), ForceMode.Impulse);
            scene.Tick(Dt);
            Assert.That(rb.angularVelocity, Is.EqualTo(Vector3.Zero));
            Assert.That(rb.rotation, Is.EqualTo(Quaternion.Identity));
            Assert.That(scene.world.GetBody(rb.body).InverseInertiaWorld.C1.Y, Is.EqualTo(0f));
        }

        [Test]
        public void FreezeRotationZ_keeps_the_body_from_turning_about_z()
        {
            PhysicsScene scene = ZeroGravityScene();
            Rigidbody rb = Ball(scene);
            rb.constraints = RigidbodyConstraints.FreezeRotationZ;
            rb.angularVelocity = new Vector3(1, 0, 1);
            for (int k = 0; k < 16; k++) scene.Tick(Dt);
            Vector3 turned = Mathematics.Rotation.ToRotationVector(rb.rotation);
            Assert.That(turned.X, Is.EqualTo(16 * Dt).Within(1e-5f));
            Assert.That(turned.Z, Is.EqualTo(0f).Within(1e-6f));
        }

        [Test]
        public void Interpolation_modes_show_previous_blend_current_and_prediction()
        {
            WorldSettings settings = WorldSettings.Default;
            settings.Gravity = Vector3.Zero;
            var scene = new PhysicsScene(settings, 0.25f);
            Rigidbody none = Ball(scene);
            Rigidbody blend = Ball(scene, new Vector3(0, 5, 0));
            Rigidbody ahead = Ball(scene, new Vector3(0, 10, 0));
            blend.interpolation = RigidbodyInterpolation.Interpolate;
            ahead.interpolation = RigidbodyInterpolation.Extrapolate;
            foreach (Rigidbody rb in new[] { none, blend, ahead }) rb.linearVelocity = new Vector3(1, 0, 0);
            scene.Tick(0.25f);   // one step: bodies at x = 0.25
            scene.Tick(0.125f);  // no step, half way to the next
            Assert.That(none.transform.position.X, Is.EqualTo(0.25f).Within(1e-6f));
            Assert.That(blend.transform.position.X, Is.EqualTo(0.125f).Within(1e-6f), "lerp(0, 0.25, 0.5)");
            Assert.That(ahead.transform.position.X, Is.EqualTo(0.375f).Within(1e-6f), "0.25 + v * 0.125");
            Assert.That(blend.position.X, Is.EqualTo(0.25f).Within(1e-6f), "the body itself is at the step pose");
            scene.Tick(0.125f);  // completes the second step
            Assert.That(blend.transform.position.X, Is.EqualTo(0.25f).Within(1e-6f), "alpha 0: the previous step's pose");
        }

        [Test]
        public void Moving_the_transform_teleports_the_body_before_the_next_step()
        {
            PhysicsScene scene = ZeroGravityScene();
            Rigidbody rb = Ball(scene);
            rb.linearVelocity = new Vector3(1, 0, 0);
            scene.Tick(Dt);
            rb.transform.position = new Vector3(0, 3, 0);
            scene.Tick(Dt);
            Assert.That(rb.position.Y, Is.EqualTo(3f));
            Assert.That(rb.position.X, Is.EqualTo(Dt).Within(1e-7f), "velocity kept, one step from the new place");
        }

        [Test]
        public void MovePosition_on_a_kinematic_body_moves_it_with_the_velocity_that_reaches_the_target()
        {
            PhysicsScene scene = ZeroGravityScene();
            Rigidbody rb = Ball(scene);
            rb.isKinematic = true;
            Assert.That(scene.world.GetBody(rb.body).Type, Is.EqualTo(BodyType.Kinematic));
            rb.MovePosition(new Vector3(0.5f, 0, 0));
            rb.MoveRotation(Quaternion.CreateFromAxisAngle(Vector3.UnitY, 0.25f));
            var probe = rb.entity.AddComponent<VelocityProbe>();
            scene.Tick(Dt);
            Assert.That(rb.position.X, Is.EqualTo(0.5f).Within(1e-6f));
            Assert.That(probe.SeenInMessages.X, Is.EqualTo(0.5f / Dt).Within(1e-2f), "the step ran at the reaching velocity");
            Assert.That(Mathematics.Rotation.ToRotationVector(rb.rotation).Y, Is.EqualTo(0.25f).Within(1e-5f));
            scene.Tick(Dt);
            Assert.That(rb.linearVelocity, Is.EqualTo(Vector3.Zero), "without a new target it stops");
            rb.isKinematic = false;
            Assert.That(scene.world.GetBody(rb.body).Mass, Is.EqualTo(2f).Within(1e-6f), "mass returns with the dynamic type");
        }

        public class VelocityProbe : Behaviour
        {
            public Vector3 SeenInMessages;
            protected override void Update() { }
            protected override void FixedUpdate() { }
            protected override void LateUpdate() => SeenInMessages = GetComponent<Rigidbody>()!.linearVelocity;
        }

        [Test]
        public void Sleep_stops_the_body_until_a_force_wakes_it()
        {
            PhysicsScene scene = ZeroGravityScene();
            Rigidbody rb = Ball(scene);
            rb.linearVelocity = new Vector3(1, 0, 0);
            rb.Sleep();
            Assert.That(rb.IsSleeping(), Is.True);
            scene.Tick(Dt);
            Assert.That(rb.position.X, Is.EqualTo(0f));
            rb.AddForce(Vector3.UnitX, ForceMode.VelocityChange);
            Assert.That(rb.IsSleeping(), Is.False);
        }

        [Test]
        public void Child_colliders_form_a_compound_whose_centre_of_mass_is_the_volume_average()
        {
            PhysicsScene scene = ZeroGravityScene();
            Entity root = scene.CreateEntity("Dumbbell");
            root.AddComponent<SphereCollider>();                 // added before the Rigidbody: static at first
            Entity child = scene.CreateEntity("Weight", new Vector3(2, 0, 0), parent: root);
            var childSphere = child.AddComponent<SphereCollider>();
            Assert.That(scene.world.BodyCount, Is.EqualTo(2), "two static colliders");
            var rb = root.AddComponent<Rigidbody>();
            Assert.That(scene.world.BodyCount, Is.EqualTo(1), "both moved onto the rigidbody");
            Assert.That(childSphere.attachedRigidbody, Is.SameAs(rb));
            Assert.That(rb.centerOfMass.X, Is.EqualTo(1f).Within(1e-5f));
            rb.centerOfMass = new Vector3(0.5f, 0, 0);
            Assert.That(scene.world.GetBody(rb.body).LocalCenterOfMass.X, Is.EqualTo(0.5f).Within(1e-6f));
            scene.DestroyImmediate(rb);
            Assert.That(childSphere.attachedRigidbody, Is.Null);
            Assert.That(scene.world.BodyCount, Is.EqualTo(2), "without the rigidbody the colliders are static again");
        }

        [Test]
        public void Deactivating_an_entity_removes_its_body_and_reactivating_restores_its_velocity()
        {
            PhysicsScene scene = ZeroGravityScene();
            Rigidbody rb = Ball(scene);
            rb.linearVelocity = new Vector3(0, 0, 2);
            rb.entity.SetActive(false);
            Assert.That(scene.world.BodyCount, Is.EqualTo(0));
            Assert.That(rb.body.IsNone, Is.True);
            rb.entity.SetActive(true);
            Assert.That(scene.world.BodyCount, Is.EqualTo(1));
            Assert.That(rb.linearVelocity.Z, Is.EqualTo(2f));
        }

        public class Thruster : Behaviour
        {
            Rigidbody? _rb;
            protected override void Start() => _rb = GetComponent<Rigidbody>();
            protected override void FixedUpdate()
            {
                _rb!.AddForce(new Vector3(0, 9.81f * _rb.mass, 0));
                _rb.AddTorque(new Vector3(0, 0.01f, 0), ForceMode.Acceleration);
            }
            public float Height;
            protected override void Update() => Height = transform.position.Y;
        }

        [Test]
        public void A_warm_component_frame_allocates_nothing()
        {
            var scene = new PhysicsScene(WorldSettings.Default, 1f / 50f);
            for (int k = 0; k < 20; k++)
            {
                Rigidbody rb = Ball(scene, new Vector3(k * 3, 5, 0));
                rb.interpolation = k % 2 == 0 ? RigidbodyInterpolation.Interpolate : RigidbodyInterpolation.Extrapolate;
                rb.constraints = k % 3 == 0 ? RigidbodyConstraints.FreezeRotationX : RigidbodyConstraints.None;
                rb.entity.AddComponent<Thruster>();
            }
            Entity ground = scene.CreateEntity("Ground", new Vector3(0, -1, 0));
            ground.AddComponent<BoxCollider>().size = new Vector3(100, 1, 100);
            long bytes = AllocationProbe.SteadyStateBytes(() => scene.Tick(1f / 60f));
            Assert.That(bytes, Is.EqualTo(0));
        }
    }
}
