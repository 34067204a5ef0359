using UnityEngine;
using BridgeContact = Fulcrum.Components.BridgeContact;
using IBridgeContactListener = Fulcrum.Components.IBridgeContactListener;
using PhysicsBridge = Fulcrum.Components.PhysicsBridge;

namespace BridgeSample
{
    /// <summary>
    /// Runs the bridge sample inside Unity: add it to any GameObject and press Play. It creates
    /// (or uses the assigned) floor, paddle and ball Transforms, registers them with a
    /// PhysicsBridge through <see cref="TransformEntity"/>, slides the paddle from
    /// FixedUpdate and lets the bridge move the ball; contacts go to the Console. Only Unity
    /// compiles this folder (the console project under Samples~/.dotnet leaves it out).
    /// </summary>
    public sealed class BridgeSampleBehaviour : MonoBehaviour, IBridgeContactListener
    {
        /// <summary>Optional Transforms for the three objects; empty ones are created at Play.</summary>
        public Transform floor, paddle, ball;

        PhysicsBridge _bridge;

        void OnEnable()
        {
            floor = OrCreate(floor, "floor", BridgeScene.FloorStart);
            paddle = OrCreate(paddle, "paddle", BridgeScene.PaddleStart);
            ball = OrCreate(ball, "ball", BridgeScene.BallStart);
            _bridge = BridgeScene.Create(new TransformEntity(floor), new TransformEntity(paddle), new TransformEntity(ball), this, threaded: false);
        }

        void OnDisable()
        {
            // The bridge owns a world (and, when threaded, a thread): release it with play mode.
            _bridge?.Dispose();
            _bridge = null;
        }

        void FixedUpdate()
        {
            if (_bridge == null) return;
            float dt = Time.fixedDeltaTime;
            paddle.position = paddle.position + new Vector3(BridgeScene.PaddleSpeed * dt, 0, 0);
            _bridge.SyncFromGame();
            _bridge.Step(dt);
            _bridge.SyncToGame();
        }

        /// <summary>Begin and end contacts go to the Console.</summary>
        public void OnContact(in BridgeContact c)
        {
            if (c.Kind == Fulcrum.Collision.ContactEventKind.Persist) return;
            Debug.Log($"{c.Kind} {c.EntityA} / {c.EntityB} at t = {c.Time:F3} s, impulse {c.NormalImpulse:F2} N s");
        }

        void OnDrawGizmos()
        {
            if (_bridge == null) return;
            Gizmos.color = Color.red;
            Gizmos.DrawWireCube(floor.position, new Vector3(20, 1, 20));
            Gizmos.DrawWireCube(paddle.position, new Vector3(0.5f, 1, 2));
            Gizmos.DrawWireSphere(ball.position, 0.5f);
        }

        static Transform OrCreate(Transform t, string name, System.Numerics.Vector3 start)
        {
            if (t != null) return t;
            t = new GameObject(name).transform;
            t.position = new Vector3(start.X, start.Y, start.Z);
            return t;
        }
    }
}
