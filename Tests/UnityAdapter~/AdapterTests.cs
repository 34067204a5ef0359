using System;
using System.IO;
using System.Reflection;
using Fulcrum.Unity;
using NUnit.Framework;
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Tests.UnityAdapter
{
    /// <summary>
    /// The Unity adapter run on the stand-in engine: GameObjects with Fulcrum components, played
    /// frame by frame (FixedUpdate, Update, LateUpdate) as Unity would. Checked against free
    /// fall, the shapes' geometry and the headless components the adapter drives.
    /// </summary>
    public class AdapterTests
    {
        const float Dt = 1f / 60f;

        [SetUp]
        public void NewScene() => FakeEngine.NewScene(Dt);

        static void Play(int steps)
        {
            for (int k = 0; k < steps; k++)
            {
                FakeEngine.FixedStep();
                FakeEngine.Frame();
            }
        }

        static FulcrumBoxCollider Ground()
        {
            var g = new GameObject("Ground");
            g.transform.position = new Vector3(0, -0.5f, 0);
            FulcrumBoxCollider c = g.AddComponent<FulcrumBoxCollider>();
            c.size = new Vector3(20, 1, 20);
            return c;
        }

        static FulcrumRigidbody Ball(string name, Vector3 at, float radius = 0.5f)
        {
            var go = new GameObject(name);
            go.transform.position = at;
            FulcrumRigidbody rb = go.AddComponent<FulcrumRigidbody>();
            go.AddComponent<FulcrumSphereCollider>().radius = radius;
            return rb;
        }

        [Test]
        public void A_rigidbody_falls_as_the_closed_form_says_and_its_GameObject_follows()
        {
            FulcrumRigidbody ball = Ball("Ball", new Vector3(0, 10, 0));
            Play(30);
            // Semi-implicit Euler: after n steps y = y0 - g dt^2 n (n + 1) / 2.
            float expected = 10f - 9.81f * Dt * Dt * 30 * 31 / 2f;
            Assert.That(ball.transform.position.y, Is.EqualTo(expected).Within(1e-3f));
            Assert.That(ball.velocity.y, Is.EqualTo(-9.81f * 0.5f).Within(1e-3f));
        }

        [Test]
        public void Properties_set_from_code_after_AddComponent_reach_the_running_world()
        {
            FulcrumBoxCollider ground = Ground();
            Assert.That(((F.BoxCollider)ground.Collider!).size.X, Is.EqualTo(20f), "set after OnEnable, applied at once");
            FulcrumRigidbody ball = Ball("Ball", new Vector3(0, 2, 0));
            ball.mass = 3f;
            ball.useGravity = false;
            Assert.That(ball.Body!.mass, Is.EqualTo(3f));
            Play(10);
            Assert.That(ball.transform.position.y, Is.EqualTo(2f).Within(1e-5f), "gravity off");
            Assert.Throws<ArgumentException>(() => ball.mass = -1f, "the headless component checks the value");
            FulcrumWorld.Instance.gravity = new Vector3(0, 0, -1);
            Assert.That(FulcrumWorld.Instance.Scene.world.Settings.Gravity.Z, Is.EqualTo(-1f));
        }

        // What the inspector does in play mode: write the serialized field, then call OnValidate.
        static void InspectorEdit(object component, string field, object value)
        {
            Type t = component.GetType();
            FieldInfo? f = null;
            for (Type? k = t; k != null && f == null; k = k.BaseType) f = k.GetField(field, BindingFlags.Instance | BindingFlags.NonPublic | BindingFlags.DeclaredOnly);
            f!.SetValue(component, value);
            MethodInfo? validate = null;
            for (Type? k = t; k != null && validate == null; k = k.BaseType) validate = k.GetMethod("OnValidate", BindingFlags.Instance | BindingFlags.NonPublic | BindingFlags.DeclaredOnly);
            validate!.Invoke(component, null);
        }

        [Test]
        public void Inspector_edits_in_play_mode_are_clamped_as_Unity_does_and_reach_the_world()
        {
            FulcrumBoxCollider ground = Ground();
            FulcrumRigidbody ball = Ball("Ball", new Vector3(0, 3, 0));
            InspectorEdit(ball, "m_Mass", -5f);
            Assert.That(ball.mass, Is.EqualTo(Limits.MinMass), "clamped, not thrown");
            Assert.That(ball.Body!.mass, Is.EqualTo(Limits.MinMass));
            InspectorEdit(ground, "m_Size", new Vector3(4, 1, 4));
            Assert.That(((F.BoxCollider)ground.Collider!).size.X, Is.EqualTo(4f));
            InspectorEdit(ground, "m_Bounciness", 3f);
            Assert.That(ground.bounciness, Is.EqualTo(1f));
            Assert.That(ground.material!.bounciness, Is.EqualTo(1f));
            FulcrumWorld world = FulcrumWorld.Instance;
            InspectorEdit(world, "m_Iterations", 0);
            Assert.That(world.Scene.world.Settings.Iterations, Is.EqualTo(1));
        }

        [Test]
        public void A_child_collider_of_a_moving_body_keeps_its_shape_from_step_to_step()
        {
            Ground();
            FulcrumRigidbody body = Ball("Body", new Vector3(0, 3, 0));
            var child = new GameObject("Arm");
            child.transform.parent = body.transform;
            child.transform.position = new Vector3(1, 3, 0);
            FulcrumBoxCollider arm = child.AddComponent<FulcrumBoxCollider>();
            arm.size = new Vector3(0.5f, 0.2f, 0.2f);
            Play(1);
            F.Collider headless = arm.Collider!;
            ShapeHandle shape = headless.shape;
            for (int k = 0; k < 40; k++)
            {
                Play(1);
                Assert.That(headless.shape, Is.EqualTo(shape), $"step {k}: the shape was rebuilt (its contacts and warm starts lost)");
            }
            Assert.That(body.transform.position.y, Is.LessThan(2f), "the body did move");
            Assert.That(child.transform.position.x, Is.EqualTo(1f).Within(0.05f), "and the child with it");
        }

        [Test]
        public void A_collider_only_object_moved_by_the_game_is_rebuilt_once_not_every_step()
        {
            FulcrumBoxCollider wall = Ground();
            Play(2);
            ShapeHandle before = wall.Collider!.shape;
            wall.transform.position = new Vector3(0, -0.4f, 0);
            Play(1);
            ShapeHandle after = wall.Collider!.shape;
            Assert.That(after, Is.Not.EqualTo(before), "the move reached the world");
            Assert.That(FulcrumWorld.Instance.Scene.world.GetBody(FulcrumWorld.Instance.Scene.world.GetShapeBody(after)).Position.Y, Is.EqualTo(-0.4f).Within(1e-5f));
            Play(20);
            Assert.That(wall.Collider!.shape, Is.EqualTo(after), "no rebuild while it stays put");
        }

        sealed class Listener : MonoBehaviour, IFulcrumCollisionHandler, IFulcrumJointBreakHandler
        {
            public int Enter, Stay, Exit, Breaks;
            public float BreakForce;
            public void OnFulcrumCollisionEnter(F.Collision collision) => Enter++;
            public void OnFulcrumCollisionStay(F.Collision collision) => Stay++;
            public void OnFulcrumCollisionExit(F.Collision collision) => Exit++;
            public void OnFulcrumJointBreak(float breakForce) { Breaks++; BreakForce = breakForce; }
        }

        [Test]
        public void Collision_handlers_hear_a_landing_once_then_stay_messages()
        {
            Ground();
            FulcrumRigidbody ball = Ball("Ball", new Vector3(0, 1, 0));
            Listener l = ball.gameObject.AddComponent<Listener>();
            Play(60);
            Assert.That(l.Enter, Is.EqualTo(1));
            Assert.That(l.Stay, Is.GreaterThan(10));
            Assert.That(l.Exit, Is.EqualTo(0));
        }

        [Test]
        public void A_joint_that_breaks_tells_the_handlers_and_its_component_goes()
        {
            FulcrumRigidbody ball = Ball("Hanging", new Vector3(0, 2, 0));
            FulcrumFixedJoint joint = ball.gameObject.AddComponent<FulcrumFixedJoint>();
            Listener l = ball.gameObject.AddComponent<Listener>();
            Play(5);
            Assert.That(ball.transform.position.y, Is.EqualTo(2f).Within(0.01f), "held");
            joint.breakForce = 5f;                      // weight 9.81 N
            Play(5);
            Assert.That(l.Breaks, Is.EqualTo(1));
            Assert.That(l.BreakForce, Is.GreaterThan(5f));
            Assert.That(ball.GetComponent<FulcrumFixedJoint>() == null, Is.True, "destroyed, as Unity does");
            Play(10);
            Assert.That(ball.transform.position.y, Is.LessThan(1.9f), "falls once free");
        }

        [Test]
        public void A_joint_connects_to_a_body_enabled_after_it()
        {
            FulcrumRigidbody a = Ball("A", new Vector3(0, 2, 0));
            FulcrumRigidbody b = Ball("B", new Vector3(1, 2, 0));
            b.enabled = false;
            FulcrumHingeJoint joint = a.gameObject.AddComponent<FulcrumHingeJoint>();
            joint.connectedBody = b;
            Assert.That(joint.Joint!.connectedBody, Is.Null, "B has no body yet: the world for now");
            b.enabled = true;
            Assert.That(joint.Joint!.connectedBody, Is.SameAs(b.Body), "connected once B is enabled");
            Play(30);
            Assert.That(Vector3.Distance(a.transform.position, b.transform.position), Is.EqualTo(1f).Within(0.02f), "the two fall together, held 1 m apart");
            Assert.That(a.transform.position.y, Is.LessThan(1.5f), "and fall: no longer held by the world");
        }

        [Test]
        public void A_hinge_spring_in_Unity_units_settles_at_its_target()
        {
            FulcrumWorld.Instance.gravity = Vector3.zero;
            var wheel = new GameObject("Wheel");
            FulcrumRigidbody rb = wheel.AddComponent<FulcrumRigidbody>();
            rb.mass = 6f;                                // a 1 m cube: I = 1 kg m^2
            rb.angularDamping = 0f;
            wheel.AddComponent<FulcrumBoxCollider>();
            FulcrumHingeJoint hinge = wheel.AddComponent<FulcrumHingeJoint>();
            hinge.axis = Vector3.up;
            hinge.spring = new F.JointSpring { spring = 4f, damper = 4f, targetPosition = 30f };
            hinge.useSpring = true;
            Play(300);
            Assert.That(hinge.angle, Is.EqualTo(30f).Within(0.5f));
        }

        [Test]
        public void Physics_queries_answer_with_the_Unity_colliders()
        {
            FulcrumBoxCollider ground = Ground();
            FulcrumRigidbody ball = Ball("Ball", new Vector3(3, 0.5f, 0));
            Play(1);
            Assert.That(FulcrumPhysics.Raycast(new Vector3(0, 10, 0), Vector3.down, out FulcrumRaycastHit hit), Is.True);
            Assert.That(hit.collider, Is.SameAs(ground));
            Assert.That(hit.distance, Is.EqualTo(10f).Within(1e-3f));
            Assert.That(hit.rigidbody == null, Is.True, "static");
            Assert.That(FulcrumPhysics.Raycast(new Ray(new Vector3(3, 10, 0), Vector3.down), out hit), Is.True);
            Assert.That(hit.rigidbody, Is.SameAs(ball));
            Assert.That(FulcrumPhysics.OverlapSphere(new Vector3(3, 0.5f, 0), 0.1f), Is.EquivalentTo(new[] { ball.GetComponent<FulcrumSphereCollider>() }));
            var results = new FulcrumCollider[4];
            Assert.That(FulcrumPhysics.OverlapBoxNonAlloc(new Vector3(3, 0.5f, 0), Vector3.one, results, Quaternion.identity), Is.EqualTo(2));
            Assert.That(FulcrumPhysics.CheckSphere(new Vector3(-3, 0.4f, 0), 0.5f), Is.True);
            Assert.That(FulcrumPhysics.CheckSphere(new Vector3(-3, 0.6f, 0), 0.5f), Is.False);
            Assert.That(ball.GetComponent<FulcrumSphereCollider>().ClosestPoint(new Vector3(3, 5, 0)).y, Is.EqualTo(1f).Within(1e-3f));
        }

        [Test]
        public void IgnoreCollision_lets_the_ball_fall_through_the_ground()
        {
            FulcrumBoxCollider ground = Ground();
            FulcrumRigidbody ball = Ball("Ball", new Vector3(0, 0.5f, 0));
            FulcrumPhysics.IgnoreCollision(ball.GetComponent<FulcrumSphereCollider>(), ground);
            Play(30);
            Assert.That(ball.transform.position.y, Is.LessThan(-0.5f));
        }

        // A closed cube of side 0.4 m: 8 vertices, 12 triangles.
        static Mesh Cube()
        {
            var v = new Vector3[8];
            for (int i = 0; i < 8; i++) v[i] = new Vector3((i & 1) != 0 ? 0.2f : -0.2f, (i & 2) != 0 ? 0.2f : -0.2f, (i & 4) != 0 ? 0.2f : -0.2f);
            int[] t =
            {
                0, 2, 1, 1, 2, 3,   4, 5, 6, 5, 7, 6,   0, 1, 4, 1, 5, 4,
                2, 6, 3, 3, 6, 7,   0, 4, 2, 2, 4, 6,   1, 3, 5, 3, 7, 5,
            };
            return new Mesh { name = "Cube", vertices = v, triangles = t };
        }

        [Test]
        public void A_soft_body_from_a_mesh_lands_on_the_ground_and_its_render_mesh_follows_without_allocating()
        {
            Ground();
            var jelly = new GameObject("Jelly");
            jelly.transform.position = new Vector3(0, 0.5f, 0);
            jelly.AddComponent<MeshFilter>().sharedMesh = Cube();
            FulcrumSoftBody soft = jelly.AddComponent<FulcrumSoftBody>();
            Assert.That(soft.TetMesh, Is.Not.Null);
            Assert.That(soft.TetMesh!.TetrahedronCount, Is.GreaterThan(10));
            Play(240);

            Mesh shown = jelly.GetComponent<MeshFilter>().mesh;
            Vector3[] local = shown.vertices;
            Assert.That(local.Length, Is.EqualTo(8), "the render mesh keeps its vertices");
            float lowest = float.MaxValue, highest = float.MinValue;
            foreach (Vector3 p in local)
            {
                Vector3 world = jelly.transform.TransformPoint(p);
                lowest = Math.Min(lowest, world.y);
                highest = Math.Max(highest, world.y);
            }
            TestContext.Out.WriteLine($"jelly at 4 s: lowest vertex {lowest * 1000:F1} mm, height {(highest - lowest) * 1000:F1} mm");
            Assert.That(lowest, Is.EqualTo(0f).Within(0.005f), "resting on the ground's top (5 mm contact gap at most)");
            // Under its own weight a 0.4 m, 1e5 Pa cube with free sides shortens rho g L^2 / 2E = 7.8 mm;
            // this coarse mesh (6 cells, nu 0.45, its base gripped by friction) is stiffer: 2.2 mm.
            Assert.That(highest - lowest, Is.InRange(0.392f, 0.3995f), "sagged a little under its weight, no more than the free-sided closed form");
            Assert.That(jelly.transform.position.y, Is.EqualTo(0.5f), "the transform stays; the vertices move");
            Assert.That(shown.normals.Length, Is.EqualTo(8));
            Assert.That(shown.normals[7].y, Is.GreaterThan(0.3f), "the top corner's normal points up and out");

            MethodInfo late = typeof(FulcrumSoftBody).GetMethod("LateUpdate", BindingFlags.Instance | BindingFlags.NonPublic)!;
            var call = (Action)late.CreateDelegate(typeof(Action), soft);
            Assert.That(Fulcrum.Tests.Components.AllocationProbe.SteadyStateBytes(call), Is.EqualTo(0), "LateUpdate allocates nothing");
        }

        [Test]
        public void A_convex_collider_on_a_body_rests_on_its_lowest_vertex()
        {
            Ground();
            var rock = new GameObject("Rock");
            rock.transform.position = new Vector3(0, 1, 0);
            rock.transform.localScale = new Vector3(2, 2, 2);
            rock.AddComponent<MeshFilter>().sharedMesh = Cube();
            rock.AddComponent<FulcrumRigidbody>();
            rock.AddComponent<FulcrumConvexCollider>();
            Play(90);
            Assert.That(rock.transform.position.y, Is.EqualTo(0.4f).Within(0.02f), "a 0.4 m cube scaled by 2 is 0.8 m tall: its centre rests at 0.4 m");
        }

        [Test]
        public void The_adapter_uses_only_Unity_members_of_the_stand_in()
        {
            string dir = Path.Combine(FindRoot(), "Runtime", "Unity");
            foreach (string file in Directory.GetFiles(dir, "*.cs"))
                Assert.That(File.ReadAllText(file), Does.Not.Contain("Fake"), $"{Path.GetFileName(file)} reaches into the stand-in's test hooks");
        }

        static string FindRoot()
        {
            for (string? d = TestContext.CurrentContext.TestDirectory; d != null; d = Path.GetDirectoryName(d))
                if (File.Exists(Path.Combine(d, "package.json")) && Directory.Exists(Path.Combine(d, "Runtime"))) return d;
            throw new DirectoryNotFoundException("the package root (package.json next to Runtime/) was not found above the test directory");
        }
    }
}
