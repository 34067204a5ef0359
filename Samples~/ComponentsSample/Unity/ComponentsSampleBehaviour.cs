using UnityEngine;

namespace ComponentsSample
{
    /// <summary>
    /// Runs the sample's headless component scene inside Unity: add it to any GameObject and
    /// press Play. Unity's FixedUpdate drives <c>PhysicsScene.Tick</c>, the behaviours'
    /// messages go to the Console through <c>Debug.Log</c>, the crate and the ball are drawn as
    /// gizmos, and two optional Transforms follow them. Only Unity compiles this folder (the
    /// console project under Samples~/.dotnet leaves it out).
    /// </summary>
    public sealed class ComponentsSampleBehaviour : MonoBehaviour
    {
        /// <summary>Optional: a Transform that follows the crate.</summary>
        public Transform crateView;

        /// <summary>Optional: a Transform that follows the ball.</summary>
        public Transform ballView;

        ComponentsScene _sample;

        void OnEnable()
        {
            Reporter.Log = Debug.Log;
            _sample = ComponentsScene.Create(Time.fixedDeltaTime);
        }

        void OnDisable() => _sample = null;

        // One Tick of exactly one fixed step per FixedUpdate: Unity already runs the fixed-step loop.
        void FixedUpdate()
        {
            if (_sample == null) return;
            _sample.Scene.Tick(_sample.Scene.fixedDeltaTime);
            Follow(crateView, _sample.Crate);
            Follow(ballView, _sample.Ball);
        }

        static void Follow(Transform view, Fulcrum.Components.Entity entity)
        {
            if (view == null) return;
            System.Numerics.Vector3 p = entity.transform.position;
            System.Numerics.Quaternion q = entity.transform.rotation;
            view.SetPositionAndRotation(new Vector3(p.X, p.Y, p.Z), new Quaternion(q.X, q.Y, q.Z, q.W));
        }

        void OnDrawGizmos()
        {
            if (_sample == null) return;
            Gizmos.color = Color.red;
            System.Numerics.Vector3 c = _sample.Crate.transform.position;
            Gizmos.DrawWireCube(new Vector3(c.X, c.Y, c.Z), Vector3.one);
            System.Numerics.Vector3 b = _sample.Ball.transform.position;
            Gizmos.DrawWireSphere(new Vector3(b.X, b.Y, b.Z), 0.5f);
        }
    }
}
