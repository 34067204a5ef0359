#nullable enable
using System.Collections.Generic;
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>
    /// Drives a headless <see cref="F.PhysicsScene"/> from Unity's loop: at the end of each
    /// FixedUpdate (after every other script's, so their forces count) it copies transforms
    /// moved by game code into the scene and calls <see cref="F.PhysicsScene.Simulate"/>; before
    /// Update (through <see cref="FulcrumInterpolator"/>) it writes the interpolated poses back
    /// to the GameObjects. Every GameObject with a Fulcrum component gets a shadow
    /// <see cref="F.Entity"/>; all logic lives in Fulcrum.Components. Put one in a scene.
    /// </summary>
    [DefaultExecutionOrder(10000)]
    [DisallowMultipleComponent]
    public sealed class FulcrumWorld : MonoBehaviour
    {
        [Tooltip("Gravity, m/s^2.")]
        public Vector3 gravity = new Vector3(0, -9.81f, 0);
        [Tooltip("Velocity iterations per substep.")]
        public int iterations = 4;
        [Tooltip("TGS substeps per step.")]
        public int substeps = 4;

        readonly Dictionary<GameObject, F.Entity> _shadows = new Dictionary<GameObject, F.Entity>();
        readonly List<GameObject> _objects = new List<GameObject>();
        F.PhysicsScene? _scene;

        /// <summary>The scene (created on first use).</summary>
        public F.PhysicsScene Scene
        {
            get
            {
                if (_scene == null)
                {
                    WorldSettings s = WorldSettings.Default;
                    s.Gravity = gravity.ToNumerics();
                    s.Iterations = iterations;
                    s.Substeps = substeps;
                    _scene = new F.PhysicsScene(s, Time.fixedDeltaTime);
                }
                return _scene;
            }
        }

        static FulcrumWorld? _instance;

        /// <summary>The FulcrumWorld of the loaded scene (one is created when none exists).</summary>
        public static FulcrumWorld Instance
        {
            get
            {
                if (_instance == null) _instance = FindObjectOfType<FulcrumWorld>();
                if (_instance == null) _instance = new GameObject("Fulcrum World").AddComponent<FulcrumWorld>();
                return _instance;
            }
        }

        void Awake()
        {
            if (_instance == null) _instance = this;
            if (GetComponent<FulcrumInterpolator>() == null) gameObject.AddComponent<FulcrumInterpolator>();
        }

        /// <summary>The shadow entity of <paramref name="go"/>, created (under its nearest shadowed ancestor) when missing.</summary>
        public F.Entity EntityFor(GameObject go)
        {
            if (_shadows.TryGetValue(go, out F.Entity e) && !e.isDestroyed) return e;
            F.Entity? parent = null;
            for (Transform t = go.transform.parent; t != null; t = t.parent)
                if (_shadows.TryGetValue(t.gameObject, out F.Entity p) && !p.isDestroyed) { parent = p; break; }
            e = Scene.CreateEntity(go.name, go.transform.position.ToNumerics(), go.transform.rotation.ToNumerics(), parent);
            e.layer = go.layer;
            e.AddComponent<UnityMessageRelay>().Target = go;
            _shadows[go] = e;
            _objects.Add(go);
            go.transform.hasChanged = false;
            return e;
        }

        /// <summary>Removes the shadow entity of <paramref name="go"/> once no enabled Fulcrum component but <paramref name="leaving"/> is left on it.</summary>
        public void Release(GameObject go, FulcrumComponent leaving)
        {
            foreach (FulcrumComponent c in go.GetComponents<FulcrumComponent>())
                if (c != leaving && c.isActiveAndEnabled) return;
            if (!_shadows.TryGetValue(go, out F.Entity e)) return;
            _shadows.Remove(go);
            _objects.Remove(go);
            if (!e.isDestroyed) Scene.DestroyImmediate(e);
        }

        void FixedUpdate()
        {
            // Game code moved these since the last write: the shadows (and their bodies) follow.
            for (int k = 0; k < _objects.Count; k++)
            {
                GameObject go = _objects[k];
                if (go == null || !go.transform.hasChanged) continue;
                F.Entity e = _shadows[go];
                e.transform.SetPositionAndRotation(go.transform.position.ToNumerics(), go.transform.rotation.ToNumerics());
            }
            Scene.Simulate(Time.fixedDeltaTime);
            WriteBack();
        }

        /// <summary>Blends poses for this frame's rendering (called before Update by <see cref="FulcrumInterpolator"/>).</summary>
        internal void Interpolate()
        {
            float alpha = Time.fixedDeltaTime > 0 ? Mathf.Clamp01((Time.time - Time.fixedTime) / Time.fixedDeltaTime) : 1f;
            Scene.ShowInterpolatedPoses(alpha);
            WriteBack();
        }

        void WriteBack()
        {
            for (int k = 0; k < _objects.Count; k++)
            {
                GameObject go = _objects[k];
                if (go == null) continue;
                F.Entity e = _shadows[go];
                if (e.GetComponent<F.Rigidbody>() == null) continue;
                go.transform.SetPositionAndRotation(e.transform.position.ToUnity(), e.transform.rotation.ToUnity());
                go.transform.hasChanged = false;
            }
        }

        void OnDestroy()
        {
            if (_instance == this) _instance = null;
        }
    }
}
