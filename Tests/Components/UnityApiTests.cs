using System;
using System.Numerics;
using Fulcrum.Components;
using NUnit.Framework;
using RaycastHit = Fulcrum.Components.RaycastHit;

namespace Fulcrum.Tests.Components
{
    /// <summary>
    /// The Unity names added to the headless components (issue 13, API alignment): each is
    /// checked against a closed form (free fall, impulse = m Δv, a spring's period, box and
    /// sphere geometry), not only for existing.
    /// </summary>
    public class UnityApiTests
    {
        const float Dt = 1f / 60f;

        static PhysicsScene Scene(bool gravity = true)
        {
            WorldSettings s = WorldSettings.Default;
            if (!gravity) s.Gravity = Vector3.Zero;
            return new PhysicsScene(s, Dt);
        }

        static BoxCollider Ground(PhysicsScene scene)
        {
            Entity g = scene.CreateEntity("Ground", new Vector3(0, -0.5f, 0));
            var c = g.AddComponent<BoxCollider>();
            c.size = new Vector3(40, 1, 40);
            return c;
        }

        static Rigidbody Ball(PhysicsScene scene, Vector3 at, float radius = 0.5f, float mass = 1f)
        {
            Entity e = scene.CreateEntity("Ball", at);
            var rb = e.AddComponent<Rigidbody>();
            rb.mass = mass;
            e.AddComponent<SphereCollider>().radius = radius;
            return rb;
        }

        [Test]
        public void Old_Unity_names_read_and_write_the_same_values()
        {
            PhysicsScene scene = Scene();
            Rigidbody rb = Ball(scene, Vector3.Zero);
            rb.velocity = new Vector3(1, 2, 3);
            Assert.That(rb.linearVelocity, Is.EqualTo(new Vector3(1, 2, 3)));
            rb.drag = 0.7f;
            Assert.That(rb.linearDamping, Is.EqualTo(0.7f));
            rb.angularDrag = 0.3f;
            Assert.That(rb.angularDamping, Is.EqualTo(0.3f));
            Assert.Throws<ArgumentException>(() => rb.drag = -1f);
        }

        [Test]
        public void FreezeRotation_sets_and_clears_only_the_rotation_bits_and_an_off_centre_push_does_not_turn_the_body()
        {
            PhysicsScene scene = Scene(gravity: false);
            Rigidbody rb = Ball(scene, Vector3.Zero);
            rb.constraints = RigidbodyConstraints.FreezePositionY;
            rb.freezeRotation = true;
            Assert.That(rb.constraints, Is.EqualTo(RigidbodyConstraints.FreezePositionY | RigidbodyConstraints.FreezeRotation));
            rb.AddForceAtPosition(new Vector3(0, 0, 10), new Vector3(0.5f, 0, 0), ForceMode.Impulse);
            scene.Tick(Dt);
            Assert.That(rb.angularVelocity.Length(), Is.EqualTo(0f).Within(1e-6f));
            Assert.That(rb.linearVelocity.Z, Is.EqualTo(10f).Within(1e-3f), "the push still moves it: Δv = J/m");
            rb.freezeRotation = false;
            Assert.That(rb.constraints, Is.EqualTo(RigidbodyConstraints.FreezePositionY));
        }

        [Test]
        public void MaxLinearVelocity_caps_free_fall_at_the_given_speed()
        {
            PhysicsScene scene = Scene();
            Rigidbody rb = Ball(scene, new Vector3(0, 100, 0));
            rb.maxLinearVelocity = 3f;
            for (int k = 0; k < 60; k++) scene.Tick(Dt);
            Assert.That(rb.linearVelocity.Y, Is.EqualTo(-3f).Within(1e-4f), "uncapped it would be -9.81 m/s after 1 s");
            Assert.That(rb.position.Y, Is.GreaterThan(100f - 3f * 1f - 0.01f), "never faster than 3 m/s, so at most 3 m in 1 s");
            Assert.Throws<ArgumentException>(() => rb.maxLinearVelocity = 0f);
            Assert.Throws<ArgumentException>(() => rb.maxAngularVelocity = float.NaN);
        }

        [Test]
        public void MaxAngularVelocity_caps_a_spin_and_keeps_its_axis()
        {
            PhysicsScene scene = Scene(gravity: false);
            Rigidbody rb = Ball(scene, Vector3.Zero);
            rb.angularDamping = 0;
            rb.maxAngularVelocity = 2f;
            rb.angularVelocity = new Vector3(0, 6, 8);
            scene.Tick(Dt);
            Assert.That(rb.angularVelocity.Length(), Is.EqualTo(2f).Within(1e-4f));
            Assert.That(Vector3.Normalize(rb.angularVelocity).Z, Is.EqualTo(0.8f).Within(1e-4f));
        }

        [Test]
        public void DetectCollisions_false_lets_a_body_fall_through_the_ground_but_queries_still_see_it()
        {
            PhysicsScene scene = Scene();
            Ground(scene);
            Rigidbody rb = Ball(scene, new Vector3(0, 0.5f, 0));
            for (int k = 0; k < 30; k++) scene.Tick(Dt);
            Assert.That(rb.position.Y, Is.EqualTo(0.5f).Within(0.02f), "rests on the ground");
            rb.detectCollisions = false;
            for (int k = 0; k < 30; k++) scene.Tick(Dt);
            Assert.That(rb.position.Y, Is.LessThan(-0.5f), "falls through");
            Assert.That(scene.Raycast(new Vector3(0, rb.position.Y, 5), -Vector3.UnitZ, out RaycastHit hit), Is.True);
            Assert.That(hit.rigidbody, Is.SameAs(rb), "queries still hit it");
            Assert.That(rb.mass, Is.EqualTo(1f));
        }

        [Test]
        public void AddExplosionForce_falls_off_linearly_with_the_distance_to_the_bounds_and_pushes_from_the_lowered_centre()
        {
            PhysicsScene scene = Scene(gravity: false);
            Rigidbody rb = Ball(scene, new Vector3(3, 0, 0), radius: 0.5f, mass: 2f);
            float near = rb.GetComponent<SphereCollider>()!.bounds.Min.X;
            Assert.That(near, Is.EqualTo(2.5f).Within(0.05f));
            rb.AddExplosionForce(10f, Vector3.Zero, 5f, 0f, ForceMode.Impulse);
            float expected = 10f * (1f - near / 5f) / 2f;            // J (1 - d/r) / m
            Assert.That(rb.linearVelocity.X, Is.EqualTo(expected).Within(1e-4f));
            Assert.That(rb.linearVelocity.Y, Is.EqualTo(0f).Within(1e-6f));

            rb.linearVelocity = Vector3.Zero;
            rb.AddExplosionForce(10f, Vector3.Zero, 5f, 3f, ForceMode.Impulse);
            Vector3 v = rb.linearVelocity;
            Assert.That(v.Y / v.X, Is.EqualTo(1f).Within(1e-4f), "from 3 m below: along (3, 3, 0)");
            Assert.That(v.Length(), Is.EqualTo(expected).Within(1e-4f), "the lowering changes the direction, not the size");

            rb.linearVelocity = Vector3.Zero;
            rb.AddExplosionForce(10f, new Vector3(-10, 0, 0), 5f, 0f, ForceMode.Impulse);
            Assert.That(rb.linearVelocity, Is.EqualTo(Vector3.Zero), "beyond the radius: nothing");
            rb.AddExplosionForce(10f, new Vector3(-10, 0, 0), 0f, 0f, ForceMode.Impulse);
            Assert.That(rb.linearVelocity.X, Is.EqualTo(5f).Within(1e-4f), "radius 0: full force at any distance");
            Assert.Throws<ArgumentException>(() => rb.AddExplosionForce(float.NaN, Vector3.Zero, 1f));
        }

        [Test]
        public void SweepTest_reports_how_far_the_body_can_move_ignoring_its_own_colliders()
        {
            PhysicsScene scene = Scene();
            Ground(scene);
            Entity e = scene.CreateEntity("Crate", new Vector3(0, 5, 0));
            var rb = e.AddComponent<Rigidbody>();
            e.AddComponent<BoxCollider>();
            Entity child = scene.CreateEntity("Lid", new Vector3(0, 6, 0), Quaternion.Identity, e);
            child.AddComponent<SphereCollider>().radius = 0.25f;
            Assert.That(rb.SweepTest(-Vector3.UnitY, out RaycastHit hit), Is.True);
            Assert.That(hit.distance, Is.EqualTo(4.5f).Within(0.01f), "bottom at 4.5 m above the ground's top");
            Assert.That(hit.collider.name, Is.EqualTo("Ground"));
            Assert.That(rb.SweepTest(-Vector3.UnitY, out _, 4f), Is.False, "not within 4 m");
            Assert.That(rb.SweepTest(Vector3.UnitY, out _), Is.False, "nothing above: its own lid is ignored");
        }

        [Test]
        public void BoxCast_and_CapsuleCast_stop_where_the_shape_first_touches()
        {
            PhysicsScene scene = Scene();
            BoxCollider ground = Ground(scene);
            Assert.That(scene.BoxCast(new Vector3(0, 5, 0), new Vector3(0.5f, 0.25f, 0.5f), -Vector3.UnitY, out RaycastHit hit, Quaternion.Identity), Is.True);
            Assert.That(hit.collider, Is.SameAs(ground));
            Assert.That(hit.distance, Is.EqualTo(4.75f).Within(0.01f));
            // A box turned 45 degrees about z reaches down by its half diagonal.
            Quaternion turned = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 4);
            Assert.That(scene.BoxCast(new Vector3(0, 5, 0), new Vector3(0.5f, 0.5f, 0.5f), -Vector3.UnitY, out hit, turned), Is.True);
            Assert.That(hit.distance, Is.EqualTo(5f - MathF.Sqrt(0.5f)).Within(0.01f));
            // A lying capsule (ends at x = ±1) of radius 0.3 from 4 m up.
            Assert.That(scene.CapsuleCast(new Vector3(-1, 4, 0), new Vector3(1, 4, 0), 0.3f, -Vector3.UnitY, out hit), Is.True);
            Assert.That(hit.distance, Is.EqualTo(3.7f).Within(0.01f));
            Assert.That(scene.CapsuleCast(new Vector3(-1, 4, 0), new Vector3(1, 4, 0), 0.3f, Vector3.UnitY, out _), Is.False);
        }

        [Test]
        public void Overlap_and_Check_queries_agree_with_the_geometry()
        {
            PhysicsScene scene = Scene();
            BoxCollider ground = Ground(scene);
            Rigidbody ball = Ball(scene, new Vector3(3, 0.5f, 0));
            Assert.That(scene.CheckSphere(new Vector3(3, 1.4f, 0), 0.5f), Is.True, "0.9 m centre to centre < 1 m");
            Assert.That(scene.CheckSphere(new Vector3(3, 1.6f, 0), 0.5f), Is.False, "1.1 m apart");
            Assert.That(scene.CheckBox(new Vector3(0, 0.4f, 0), new Vector3(0.5f, 0.5f, 0.5f), Quaternion.Identity), Is.True, "reaches 0.1 m into the ground");
            Assert.That(scene.CheckBox(new Vector3(0, 0.4f, 0), new Vector3(0.5f, 0.3f, 0.5f), Quaternion.Identity), Is.False, "bottom 0.1 m above it");
            Assert.That(scene.CheckCapsule(new Vector3(0, 1, 0), new Vector3(0, 3, 0), 0.9f), Is.False, "bottom at 0.1 m");
            Assert.That(scene.CheckCapsule(new Vector3(0, 1, 0), new Vector3(0, 3, 0), 1.1f), Is.True);

            Collider[] all = scene.OverlapBox(new Vector3(3, 0.5f, 0), new Vector3(1, 1, 1), Quaternion.Identity);
            Assert.That(all.Length, Is.EqualTo(2));
            Assert.That(all, Does.Contain(ground));
            Assert.That(all, Does.Contain(ball.GetComponent<SphereCollider>()));
            Span<Collider> some = new Collider[4];
            Assert.That(scene.OverlapCapsule(new Vector3(3, 1.4f, -2), new Vector3(3, 1.4f, 2), 0.6f, some), Is.EqualTo(1), "touches the ball's top only");
            Assert.That(some[0], Is.SameAs(ball.GetComponent<SphereCollider>()));
            Assert.That(scene.OverlapSphere(new Vector3(3, 0.5f, 0), 0.1f).Length, Is.EqualTo(1));
            Assert.That(scene.RaycastAll(new Vector3(3, 10, 0), -Vector3.UnitY).Length, Is.EqualTo(2));
            Assert.That(scene.RaycastAll(new Vector3(30, 10, 30), Vector3.UnitY), Is.Empty);
        }

        [Test]
        public void ClosestPoint_projects_onto_the_surface_and_returns_points_inside_unchanged()
        {
            PhysicsScene scene = Scene();
            Entity e = scene.CreateEntity("Box");
            var box = e.AddComponent<BoxCollider>();
            box.size = new Vector3(2, 2, 2);
            Assert.That(box.ClosestPoint(new Vector3(3, 0.5f, 0)), Is.EqualTo(new Vector3(1, 0.5f, 0)).Using(Tolerance(1e-4f)));
            Assert.That(box.ClosestPoint(new Vector3(0.2f, 0.3f, 0.1f)), Is.EqualTo(new Vector3(0.2f, 0.3f, 0.1f)), "inside");
            Assert.That(box.ClosestPointOnBounds(new Vector3(5, 5, 5)).X, Is.EqualTo(box.bounds.Max.X));

            // Placed elsewhere, turned 45 degrees about y: the corner at +x is at distance √2.
            Quaternion turned = Quaternion.CreateFromAxisAngle(Vector3.UnitY, MathF.PI / 4);
            Vector3 p = scene.ClosestPoint(new Vector3(15, 0, 0), box, new Vector3(10, 0, 0), turned);
            Assert.That(p, Is.EqualTo(new Vector3(10 + MathF.Sqrt(2), 0, 0)).Using(Tolerance(1e-3f)));

            var sphere = scene.CreateEntity("Sphere", new Vector3(0, 10, 0)).AddComponent<SphereCollider>();
            sphere.radius = 2f;
            Assert.That(sphere.ClosestPoint(new Vector3(0, 10, 5)), Is.EqualTo(new Vector3(0, 10, 2)).Using(Tolerance(1e-4f)));
        }

        [Test]
        public void ComputePenetration_gives_the_shortest_separating_translation_of_the_first_collider()
        {
            PhysicsScene scene = Scene();
            var a = scene.CreateEntity("A").AddComponent<BoxCollider>();
            var b = scene.CreateEntity("B").AddComponent<BoxCollider>();
            Assert.That(scene.ComputePenetration(a, new Vector3(0.8f, 0.1f, 0), Quaternion.Identity, b, Vector3.Zero, Quaternion.Identity,
                out Vector3 direction, out float distance), Is.True);
            Assert.That(distance, Is.EqualTo(0.2f).Within(1e-3f), "unit boxes 0.8 m apart overlap by 0.2 m along x");
            Assert.That(direction, Is.EqualTo(Vector3.UnitX).Using(Tolerance(1e-3f)), "A moves away from B");
            Assert.That(scene.ComputePenetration(a, new Vector3(1.1f, 0, 0), Quaternion.Identity, b, Vector3.Zero, Quaternion.Identity, out _, out _), Is.False);

            var s1 = scene.CreateEntity("S1").AddComponent<SphereCollider>();
            var s2 = scene.CreateEntity("S2").AddComponent<SphereCollider>();
            s1.radius = s2.radius = 1f;
            Assert.That(scene.ComputePenetration(s1, new Vector3(0, 0, -1.5f), Quaternion.Identity, s2, Vector3.Zero, Quaternion.Identity, out direction, out distance), Is.True);
            Assert.That(distance, Is.EqualTo(0.5f).Within(1e-4f));
            Assert.That(direction, Is.EqualTo(-Vector3.UnitZ).Using(Tolerance(1e-4f)));

            // A sphere whose centre is inside a box: the cores overlap (EPA), out through the nearest face.
            Assert.That(scene.ComputePenetration(s1, new Vector3(0, 0.3f, 0), Quaternion.Identity, b, Vector3.Zero, Quaternion.Identity, out direction, out distance), Is.True);
            Assert.That(distance, Is.EqualTo(0.2f + 1f).Within(1e-3f), "0.2 m to the top face plus the radius");
            Assert.That(direction, Is.EqualTo(Vector3.UnitY).Using(Tolerance(1e-3f)));
        }

        [Test]
        public void Collider_Raycast_sees_only_that_collider_and_material_is_a_private_copy()
        {
            PhysicsScene scene = Scene();
            BoxCollider ground = Ground(scene);
            Rigidbody ball = Ball(scene, new Vector3(0, 3, 0));
            var sphere = ball.GetComponent<SphereCollider>()!;
            var ray = new Ray(new Vector3(0, 10, 0), new Vector3(0, -2, 0));
            Assert.That(ground.Raycast(ray, out RaycastHit hit, 100f), Is.True, "the ball in between is not this collider");
            Assert.That(hit.distance, Is.EqualTo(10f).Within(1e-4f));
            Assert.That(sphere.Raycast(ray, out hit, 100f), Is.True);
            Assert.That(hit.distance, Is.EqualTo(6.5f).Within(1e-4f));
            Assert.That(sphere.Raycast(ray, out _, 6f), Is.False);

            var shared = new PhysicsMaterial("Rubber") { dynamicFriction = 0.9f, bounciness = 0.8f };
            ground.sharedMaterial = shared;
            sphere.sharedMaterial = shared;
            PhysicsMaterial own = sphere.material;
            Assert.That(own, Is.Not.SameAs(shared));
            Assert.That(own.bounciness, Is.EqualTo(0.8f));
            own.bounciness = 0.1f;
            Assert.That(shared.bounciness, Is.EqualTo(0.8f), "the shared material is untouched");
            Assert.That(sphere.material, Is.SameAs(own), "the copy is made once");
            Assert.That(scene.world.Shapes.Restitution[sphere.shape.Index], Is.EqualTo(0.1f), "and it is what the shape uses");
        }

        [Test]
        public void LayerMask_names_and_masks_follow_Unity()
        {
            Assert.That(LayerMask.NameToLayer("Ignore Raycast"), Is.EqualTo(2));
            Assert.That(LayerMask.GetMask("Default", "Water", "no such layer"), Is.EqualTo(1 | 1 << 4));
            LayerMask.SetLayerName(9, "Enemies");
            Assert.That(LayerMask.LayerToName(9), Is.EqualTo("Enemies"));
            LayerMask m = LayerMask.GetMask("Enemies");
            int asInt = m;
            Assert.That(asInt, Is.EqualTo(1 << 9));
        }

        // A solid cube of 1 m and 6 kg has I = m (1 + 1) / 12 = 1 kg m² about any axis through its centre.
        static HingeJoint Wheel(PhysicsScene scene)
        {
            Entity e = scene.CreateEntity("Wheel");
            var rb = e.AddComponent<Rigidbody>();
            rb.mass = 6f;
            rb.angularDamping = 0f;
            e.AddComponent<BoxCollider>();
            var hinge = e.AddComponent<HingeJoint>();
            hinge.axis = Vector3.UnitY;
            return hinge;
        }

        [Test]
        public void Hinge_spring_in_Unity_units_oscillates_at_the_closed_form_frequency()
        {
            PhysicsScene scene = Scene(gravity: false);
            HingeJoint hinge = Wheel(scene);
            hinge.useSpring = true;
            hinge.spring = new JointSpring { spring = 4f };   // ω = √(k/I) = 2 rad/s, T = π s
            Rigidbody rb = hinge.GetComponent<Rigidbody>()!;
            scene.Tick(Dt);
            rb.angularVelocity = new Vector3(0, 1, 0);       // θ(t) = ½ sin 2t: 28.6° peak at π/4 s
            Assert.That(hinge.velocity, Is.EqualTo(57.3f).Within(0.5f), "1 rad/s in degrees/s");
            float peak = 0, firstReturn = -1, t = 0, previous = 0;
            for (int k = 0; k < 120; k++)
            {
                scene.Tick(Dt);
                t += Dt;
                peak = Math.Max(peak, hinge.angle);
                if (firstReturn < 0 && previous > 0 && hinge.angle <= 0) firstReturn = t;
                previous = hinge.angle;
            }
            Assert.That(peak, Is.EqualTo(28.65f).Within(1.5f));
            Assert.That(firstReturn, Is.EqualTo(MathF.PI / 2).Within(0.06f), "half a period");
        }

        [Test]
        public void Hinge_spring_with_a_target_settles_at_the_target_angle()
        {
            PhysicsScene scene = Scene(gravity: false);
            HingeJoint hinge = Wheel(scene);
            hinge.useSpring = true;
            hinge.spring = new JointSpring { spring = 4f, damper = 4f, targetPosition = 20f };  // critically damped: c = 2√(kI)
            for (int k = 0; k < 300; k++) scene.Tick(Dt);
            Assert.That(hinge.angle, Is.EqualTo(20f).Within(0.5f));
            Assert.That(Math.Abs(hinge.velocity), Is.LessThan(0.5f));
            hinge.useSpring = false;
            Rigidbody rb = hinge.GetComponent<Rigidbody>()!;
            rb.angularVelocity = new Vector3(0, 0.5f, 0);
            for (int k = 0; k < 30; k++) scene.Tick(Dt);
            Assert.That(hinge.velocity, Is.EqualTo(28.65f).Within(0.5f), "no spring: it turns freely");
            Assert.Throws<ArgumentException>(() => hinge.spring = new JointSpring { spring = -1f });
            Assert.Throws<ArgumentException>(() => hinge.spring = new JointSpring { spring = 1f, targetPosition = 270f });
        }

        [Test]
        public void New_queries_allocate_nothing_once_warm()
        {
            PhysicsScene scene = Scene();
            BoxCollider ground = Ground(scene);
            Rigidbody ball = Ball(scene, new Vector3(0, 3, 0));
            var results = new Collider[4];
            var sphere = ball.GetComponent<SphereCollider>()!;
            long bytes = AllocationProbe.SteadyStateBytes(() =>
            {
                scene.BoxCast(new Vector3(0, 5, 0), new Vector3(0.5f, 0.5f, 0.5f), -Vector3.UnitY, out _, Quaternion.Identity);
                scene.CapsuleCast(new Vector3(-1, 4, 0), new Vector3(1, 4, 0), 0.3f, -Vector3.UnitY, out _);
                scene.OverlapBox(Vector3.Zero, Vector3.One, results, Quaternion.Identity);
                scene.CheckSphere(Vector3.Zero, 1f);
                ball.SweepTest(-Vector3.UnitY, out _);
                ground.ClosestPoint(new Vector3(0, 5, 0));
                scene.ComputePenetration(sphere, Vector3.Zero, Quaternion.Identity, ground, new Vector3(0, -0.5f, 0), Quaternion.Identity, out _, out _);
            });
            Assert.That(bytes, Is.EqualTo(0));
        }

        static VectorsWithin Tolerance(float t) => new VectorsWithin(t);

        /// <summary>Vectors equal when no component differs by more than the tolerance.</summary>
        sealed class VectorsWithin : System.Collections.Generic.IEqualityComparer<Vector3>
        {
            readonly float _t;
            public VectorsWithin(float t) { _t = t; }
            public bool Equals(Vector3 a, Vector3 b) => Math.Abs(a.X - b.X) <= _t && Math.Abs(a.Y - b.Y) <= _t && Math.Abs(a.Z - b.Z) <= _t;
            public int GetHashCode(Vector3 v) => 0;
        }
    }
}
