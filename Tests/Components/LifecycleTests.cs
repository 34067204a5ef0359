using System.Collections.Generic;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Components;
using NUnit.Framework;

namespace Fulcrum.Tests.Components
{
    /// <summary>Writes every message it gets to a shared log, as "name:Message".</summary>
    public class Recorder : Behaviour
    {
        /// <summary>Log and tag given to recorders created next on this thread (Awake runs inside AddComponent).</summary>
        [System.ThreadStatic] public static List<string>? NextLog;
        [System.ThreadStatic] public static string? NextTag;

        public List<string> Log = NextLog ?? new List<string>();
        public string Tag = NextTag ?? "";

        void Add(string m) => Log.Add(Tag.Length > 0 ? Tag + ":" + m : m);
        protected override void Awake() => Add("Awake");
        protected override void OnEnable() => Add("OnEnable");
        protected override void Start() => Add("Start");
        protected override void FixedUpdate() => Add("FixedUpdate");
        protected override void Update() => Add("Update");
        protected override void LateUpdate() => Add("LateUpdate");
        protected override void OnDisable() => Add("OnDisable");
        protected override void OnDestroy() => Add("OnDestroy");
        protected override void OnCollisionEnter(Fulcrum.Components.Collision c) => Add("OnCollisionEnter");
        protected override void OnCollisionStay(Fulcrum.Components.Collision c) => Add("OnCollisionStay");
        protected override void OnCollisionExit(Fulcrum.Components.Collision c) => Add("OnCollisionExit");
        protected override void OnTriggerEnter(Collider other) => Add("OnTriggerEnter");
        protected override void OnTriggerStay(Collider other) => Add("OnTriggerStay");
        protected override void OnTriggerExit(Collider other) => Add("OnTriggerExit");
    }

    public class LifecycleTests
    {
        // 0.25 s steps and frame times that are sums of powers of two keep the accumulator exact.
        static PhysicsScene NewScene() => new PhysicsScene(WorldSettings.Default, 0.25f);

        [Test]
        public void Messages_follow_Unity_order_across_frames_with_zero_one_and_two_fixed_steps()
        {
            PhysicsScene scene = NewScene();
            Entity e = scene.CreateEntity("Player");
            var r = e.AddComponent<Recorder>();
            Assert.That(r.Log, Is.EqualTo(new[] { "Awake", "OnEnable" }), "Awake and OnEnable run inside AddComponent");
            r.Log.Clear();

            scene.Tick(0.25f);
            Assert.That(r.Log, Is.EqualTo(new[] { "Start", "FixedUpdate", "Update", "LateUpdate" }));
            r.Log.Clear();

            scene.Tick(0.125f);
            Assert.That(r.Log, Is.EqualTo(new[] { "Update", "LateUpdate" }), "no fixed step in a short frame");
            r.Log.Clear();

            scene.Tick(0.375f);
            Assert.That(r.Log, Is.EqualTo(new[] { "FixedUpdate", "FixedUpdate", "Update", "LateUpdate" }), "0.125 carried + 0.375 = two steps");
            r.Log.Clear();

            r.enabled = false;
            scene.Tick(0.25f);
            r.enabled = true;
            Assert.That(r.Log, Is.EqualTo(new[] { "OnDisable", "OnEnable" }), "a disabled behaviour gets no updates");
            r.Log.Clear();

            scene.Destroy(e);
            Assert.That(r.Log, Is.Empty, "Destroy waits for the end of the frame");
            scene.Tick(0.25f);
            Assert.That(r.Log, Is.EqualTo(new[] { "FixedUpdate", "Update", "LateUpdate", "OnDisable", "OnDestroy" }));
            Assert.That(e.isDestroyed, Is.True);
            Assert.That(scene.entityCount, Is.EqualTo(0));
        }

        [Test]
        public void Collision_messages_come_after_each_physics_step_and_before_the_next_FixedUpdate()
        {
            PhysicsScene scene = NewScene();
            scene.world.Gravity = Vector3.Zero;
            Entity ground = scene.CreateEntity("Ground");
            var groundBox = ground.AddComponent<BoxCollider>();
            Entity ball = scene.CreateEntity("Ball", new Vector3(0, 2, 0));
            ball.AddComponent<Rigidbody>();
            var ballSphere = ball.AddComponent<SphereCollider>();
            var log = new List<string>();
            var r = ball.AddComponent<Recorder>();
            r.Log = log;
            scene.Tick(0.25f);
            log.Clear();

            scene.InjectContactEvent(new ContactEvent { Kind = ContactEventKind.Begin, ShapeA = groundBox.shape, ShapeB = ballSphere.shape, PointCount = 1, Normal = Vector3.UnitY });
            scene.Tick(0.5f);
            Assert.That(log, Is.EqualTo(new[] { "FixedUpdate", "OnCollisionEnter", "FixedUpdate", "Update", "LateUpdate" }));
        }

        [Test]
        public void Awake_waits_for_activation_and_Start_waits_for_enabling()
        {
            PhysicsScene scene = NewScene();
            Entity parent = scene.CreateEntity("Parent");
            Entity child = scene.CreateEntity("Child", parent: parent);
            parent.SetActive(false);
            Assert.That(child.activeInHierarchy, Is.False);
            var r = child.AddComponent<Recorder>();
            r.enabled = false;
            scene.Tick(0.25f);
            Assert.That(r.Log, Is.Empty, "nothing runs on an inactive entity");

            parent.SetActive(true);
            Assert.That(r.Log, Is.EqualTo(new[] { "Awake" }), "Awake runs on activation even when disabled");
            scene.Tick(0.25f);
            Assert.That(r.Log, Is.EqualTo(new[] { "Awake" }), "no Start while disabled");

            r.enabled = true;
            scene.Tick(0.25f);
            Assert.That(r.Log, Is.EqualTo(new[] { "Awake", "OnEnable", "Start", "FixedUpdate", "Update", "LateUpdate" }));

            r.Log.Clear();
            parent.SetActive(false);
            Assert.That(r.Log, Is.EqualTo(new[] { "OnDisable" }), "deactivating the parent disables the child's behaviours");
        }

        [Test]
        public void A_behaviour_added_during_Update_starts_next_frame_and_runs_in_creation_order()
        {
            PhysicsScene scene = NewScene();
            var log = new List<string>();
            Entity e = scene.CreateEntity("Spawner");
            Recorder.NextLog = log;
            Recorder.NextTag = "A";
            try { e.AddComponent<Recorder>(); }
            finally { Recorder.NextLog = null; Recorder.NextTag = null; }
            var spawner = e.AddComponent<SpawnOnUpdate>();
            spawner.Log = log;
            scene.Tick(0.25f);
            Assert.That(log, Is.EqualTo(new[] { "A:Awake", "A:OnEnable", "A:Start", "A:FixedUpdate", "A:Update", "B:Awake", "B:OnEnable", "A:LateUpdate" }));
            log.Clear();
            scene.Tick(0.25f);
            Assert.That(log, Is.EqualTo(new[] { "B:Start", "A:FixedUpdate", "B:FixedUpdate", "A:Update", "B:Update", "A:LateUpdate", "B:LateUpdate" }));
        }

        public class SpawnOnUpdate : Behaviour
        {
            public List<string> Log = new List<string>();
            bool _done;

            protected override void Update()
            {
                if (_done) return;
                _done = true;
                Entity other = scene.CreateEntity("B");
                Recorder.NextLog = Log;
                Recorder.NextTag = "B";
                try { other.AddComponent<Recorder>(); }
                finally { Recorder.NextLog = null; Recorder.NextTag = null; }
            }
        }
    }
}
