#nullable enable
using System.Collections.Generic;
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>
    /// Drives a headless <see cref="F.PhysicsScene"/> from Unity's loop: at the end of each
    /// FixedUpdate (after every other script's, so their forces count) it copies transforms
    /// moved by game code into the scene and calls <see cref="F.PhysicsScene.Simulate"/> with
    /// the current Time.fixedDeltaTime; before Update (through <see cref="FulcrumInterpolator"/>)
    /// it writes the interpolated poses back to the GameObjects. Every GameObject with a Fulcrum
    /// component gets a shadow <see cref="F.Entity"/>; all logic lives in Fulcrum.Components.
    /// Put one in a scene (one is created on first use otherwise).
    /// </summary>
    [DefaultExecutionOrder(10000)]
    [DisallowMultipleComponent]
    public sealed class FulcrumWorld : MonoBehaviour
    {
        [SerializeField, Tooltip("Gravity, m/s^2.")] Vector3 m_Gravity = new Vector3(0, -9.81f, 0);
        [SerializeField, Tooltip("Velocity iterations per substep (1-64).")] int m_Iterations = 4;
        [SerializeField, Tooltip("TGS substeps per step (1-64).")] int m_Substeps = 4;
        [SerializeField, Tooltip("Solver threads (1 = the main thread only).")] int m_Threads = 1;

        /// <summary>Gravity, m/s^2.</summary>
        public Vector3 gravity { get => m_Gravity; set { m_Gravity = value; PushSettings(); } }
        /// <summary>Velocity iterations per substep (1-64).</summary>
        public int iterations { get => m_Iterations; set { m_Iterations = value; PushSettings(); } }
        /// <summary>TGS substeps per step (1-64).</summary>
        public int substeps { get => m_Substeps; set { m_Substeps = value; PushSettings(); } }
        /// <summary>Solver threads (1 = the main thread only).</summary>
        public int threads { get => m_Threads; set { m_Threads = value; PushSettings(); } }

        readonly Dictionary<GameObject, F.Entity> _shadows = new Dictionary<GameObject, F.Entity>();
        readonly List<GameObject> _objects = new List<GameObject>();
        readonly Dictionary<F.Collider, FulcrumCollider> _colliders = new Dictionary<F.Collider, FulcrumCollider>();
        F.PhysicsScene? _scene;

        /// <summary>The scene (created on first use).</summary>
        public F.PhysicsScene Scene
        {
            get
            {
                if (_scene == null)
                {
                    WorldSettings s = WorldSettings.Default;
                    Apply(ref s);
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
                FulcrumWorld? w = Current;
                if (w == null) w = _instance = new GameObject("Fulcrum World").AddComponent<FulcrumWorld>();
                return w;
            }
        }

        /// <summary>The FulcrumWorld of the loaded scene, or null (never creates one).</summary>
        public static FulcrumWorld? Current
        {
            get
            {
                if (_instance == null)
#if UNITY_2023_1_OR_NEWER
                    _instance = FindAnyObjectByType<FulcrumWorld>();
#else
                    _instance = FindObjectOfType<FulcrumWorld>();
#endif
                return _instance;
            }
        }

        void Awake()
        {
            if (_instance == null) _instance = this;
            if (GetComponent<FulcrumInterpolator>() == null) gameObject.AddComponent<FulcrumInterpolator>();
        }

        // Inspector edits in play mode reach the running world (values out of range are clamped, as Unity does).
        void OnValidate()
        {
            m_Iterations = Mathf.Clamp(m_Iterations, 1, 64);
            m_Substeps = Mathf.Clamp(m_Substeps, 1, 64);
            m_Threads = Mathf.Clamp(m_Threads, 1, Limits.MaxThreads);
            PushSettings();
        }

        // The world checks the values (a bad one throws and changes nothing).
        void PushSettings()
        {
            if (_scene == null) return;
            WorldSettings s = _scene.world.Settings;
            Apply(ref s);
            _scene.world.Settings = s;
        }

        void Apply(ref WorldSettings s)
        {
            s.Gravity = m_Gravity.ToNumerics();
            s.Iterations = m_Iterations;
            s.Substeps = m_Substeps;
            s.Threads = m_Threads;
        }

        /// <summary>The shadow entity of <paramref name="go"/>, created (under its nearest shadowed ancestor) when missing.</summary>
        public F.Entity EntityFor(GameObject go)
        {
            if (_shadows.TryGetValue(go, out F.Entity? existing) && !existing!.isDestroyed) return existing;
            F.Entity? parent = null;
            for (Transform t = go.transform.parent; t != null; t = t.parent)
                if (_shadows.TryGetValue(t.gameObject, out F.Entity? p) && !p!.isDestroyed) { parent = p; break; }
            F.Entity e = Scene.CreateEntity(go.name, go.transform.position.ToNumerics(), go.transform.rotation.ToNumerics(), parent);
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
            if (!_shadows.TryGetValue(go, out F.Entity? e)) return;
            _shadows.Remove(go);
            _objects.Remove(go);
            if (!e!.isDestroyed) Scene.DestroyImmediate(e);
        }

        readonly List<FulcrumJoint> _joints = new List<FulcrumJoint>();

        internal void Register(FulcrumJoint j)
        {
            if (!_joints.Contains(j)) _joints.Add(j);
        }

        internal void Unregister(FulcrumJoint j) => _joints.Remove(j);

        // A body enabled after the joints naming it (scene load order): they connect to it now.
        internal void OnBodyEnabled(FulcrumRigidbody body)
        {
            for (int k = 0; k < _joints.Count; k++)
                if (_joints[k] != null && _joints[k].connectedBody == body) _joints[k].Reconnect();
        }

        internal void Register(F.Collider c, FulcrumCollider face) => _colliders[c] = face;

        internal void Unregister(F.Collider c) => _colliders.Remove(c);

        /// <summary>The Unity collider whose headless collider is <paramref name="c"/>, or null.</summary>
        public FulcrumCollider? FaceOf(F.Collider? c) => c != null && _colliders.TryGetValue(c, out FulcrumCollider? f) ? f : null;

        void FixedUpdate()
        {
            PushMovedTransforms();
            Scene.Simulate(Time.fixedDeltaTime);
            WriteBack();
        }

        /// <summary>Blends poses for this frame's rendering (called before Update by <see cref="FulcrumInterpolator"/>).</summary>
        internal void Interpolate()
        {
            // Moves made since the last write (in last frame's Update or LateUpdate) reach the
            // scene before the write-back below would overwrite them.
            PushMovedTransforms();
            float alpha = Time.fixedDeltaTime > 0 ? Mathf.Clamp01((Time.time - Time.fixedTime) / Time.fixedDeltaTime) : 1f;
            Scene.ShowInterpolatedPoses(alpha);
            WriteBack();
        }

        // Game code moved these since the last write: the shadows (and their bodies and shapes) follow.
        void PushMovedTransforms()
        {
            for (int k = 0; k < _objects.Count; k++)
            {
                GameObject go = _objects[k];
                if (go == null || !go.transform.hasChanged) continue;
                F.Entity e = _shadows[go];
                e.transform.SetPositionAndRotation(go.transform.position.ToNumerics(), go.transform.rotation.ToNumerics());
                go.transform.hasChanged = false;
            }
        }

        // Bodies' poses to their GameObjects. Writing a parent flags its children's transforms as
        // changed too, so every shadowed object is marked in sync afterwards: otherwise a child
        // collider of a moving body (or a collider-only object) would be pushed back next step
        // and its shape rebuilt every FixedUpdate (warm starting and manifold reuse lost).
        void WriteBack()
        {
            for (int k = 0; k < _objects.Count; k++)
            {
                GameObject go = _objects[k];
                if (go == null) continue;
                F.Entity e = _shadows[go];
                if (e.GetComponent<F.Rigidbody>() == null) continue;
                go.transform.SetPositionAndRotation(e.transform.position.ToUnity(), e.transform.rotation.ToUnity());
            }
            for (int k = 0; k < _objects.Count; k++)
            {
                GameObject go = _objects[k];
                if (go != null) go.transform.hasChanged = false;
            }
        }

        void OnDestroy()
        {
            // With domain reload off, play mode ending would otherwise leave the workers idling.
            _scene?.world.StopThreads();
            if (_instance == this) _instance = null;
        }
    }
}
