// Stand-ins for the parts of UnityEngine and UnityEditor that Fulcrum.Unity and Fulcrum.Editor
// use, with Unity's names and signatures, so that `dotnet build` can type-check the adapters and
// Tests/UnityAdapter~ can run them. Never shipped: Unity does not import folders ending in '~'.
//
// Signatures: every public member was checked against Unity's C# reference source
// (github.com/Unity-Technologies/UnityCsReference), branches 2021.3 (2021.3.58f1) and 6000.0
// (6000.0.78f1): same name, static-ness, parameter and return types. One differs by version and
// is used under #if: FindObjectOfType is obsolete from 2023.1 (FindAnyObjectByType replaces it;
// it exists from 2021.3.18). Members Unity has and these lack are not used by the adapters.
//
// Behaviour: the bodies emulate what Unity documents for the members the adapters rely on: the
// component list and lifecycle messages (Awake, OnEnable, OnDisable, OnDestroy, FixedUpdate,
// Update, LateUpdate in DefaultExecutionOrder), RequireComponent, transform hierarchy with
// hasChanged set on the transform and its children by any change, lossyScale, MeshFilter.mesh
// instantiating the shared mesh on first read, Destroy at the end of the frame. FakeEngine (at
// the end, not a Unity type) plays frames for tests. What it cannot prove is that Unity behaves
// as documented; the README's Unity section says what stays unverified.
#nullable disable
#pragma warning disable CS0067, CS0626, CS1591
using System;
using System.Collections.Generic;
using System.Reflection;

namespace UnityEngine
{
    public class Object
    {
        public string name { get; set; }

        public static T FindObjectOfType<T>() where T : Object => FakeEngine.FindFirst<T>();
        public static T FindAnyObjectByType<T>() where T : Object => FakeEngine.FindFirst<T>();

        public static void Destroy(Object obj) => FakeEngine.QueueDestroy(obj);

        // Unity's null check: a destroyed object compares equal to null.
        internal bool FakeDestroyed;
        public static bool operator ==(Object a, Object b)
        {
            bool aNull = ReferenceEquals(a, null) || a.FakeDestroyed, bNull = ReferenceEquals(b, null) || b.FakeDestroyed;
            if (aNull || bNull) return aNull && bNull;
            return ReferenceEquals(a, b);
        }
        public static bool operator !=(Object a, Object b) => !(a == b);
        public static implicit operator bool(Object exists) => exists != null;
        public override bool Equals(object other) => other is Object o ? this == o : false;
        public override int GetHashCode() => base.GetHashCode();
    }

    public class Component : Object
    {
        internal GameObject FakeOwner;
        public GameObject gameObject => FakeOwner;
        public Transform transform => FakeOwner.transform;
        public T GetComponent<T>() => FakeOwner.GetComponent<T>();
        public T GetComponentInParent<T>()
        {
            for (Transform t = transform; t != null; t = t.parent)
            {
                T c = t.gameObject.GetComponent<T>();
                if (c != null && !(c is Object o && o.FakeDestroyed)) return c;
            }
            return default;
        }
        public T[] GetComponents<T>() => FakeOwner.GetComponents<T>();
        public void GetComponents<T>(List<T> results) => FakeOwner.GetComponents(results);
        public void SendMessage(string methodName, object value, SendMessageOptions options) => FakeOwner.SendMessage(methodName, value, options);
    }

    public class Behaviour : Component
    {
        bool _enabled = true;
        internal bool FakeEnabledCalled;
        public bool enabled
        {
            get => _enabled;
            set
            {
                if (value == _enabled) return;
                _enabled = value;
                FakeEngine.Refresh(this);
            }
        }
        public bool isActiveAndEnabled => _enabled && FakeOwner != null && FakeOwner.FakeActive && !FakeDestroyed;
    }

    public class MonoBehaviour : Behaviour { }

    public sealed class GameObject : Object
    {
        internal readonly List<Component> FakeComponents = new List<Component>();
        internal bool FakeActive = true;
        readonly Transform _transform;

        public GameObject(string name)
        {
            this.name = name;
            _transform = new Transform { FakeOwner = this, name = name };
            FakeComponents.Add(_transform);
            FakeEngine.Objects.Add(this);
        }

        public Transform transform => _transform;
        public int layer { get; set; }
        public bool activeSelf => FakeActive;

        public void SetActive(bool value)
        {
            if (value == FakeActive) return;
            FakeActive = value;
            foreach (Component c in FakeComponents.ToArray())
                if (c is Behaviour b) FakeEngine.Refresh(b);
        }

        public T AddComponent<T>() where T : Component
        {
            foreach (RequireComponent r in typeof(T).GetCustomAttributes<RequireComponent>(true))
                if (GetComponent(r.FakeType) == null) FakeAdd(r.FakeType);
            return (T)FakeAdd(typeof(T));
        }

        Component FakeAdd(Type type)
        {
            var c = (Component)Activator.CreateInstance(type, true);
            c.FakeOwner = this;
            c.name = name;
            FakeComponents.Add(c);
            if (c is Behaviour b)
            {
                if (FakeActive) FakeEngine.Call(b, "Awake");
                FakeEngine.Refresh(b);
            }
            return c;
        }

        Component GetComponent(Type type)
        {
            foreach (Component c in FakeComponents)
                if (!c.FakeDestroyed && type.IsInstanceOfType(c)) return c;
            return null;
        }

        public T GetComponent<T>()
        {
            foreach (Component c in FakeComponents)
                if (!c.FakeDestroyed && c is T t) return t;
            return default;
        }

        public T[] GetComponents<T>()
        {
            var list = new List<T>();
            GetComponents(list);
            return list.ToArray();
        }

        public void GetComponents<T>(List<T> results)
        {
            results.Clear();
            foreach (Component c in FakeComponents)
                if (!c.FakeDestroyed && c is T t) results.Add(t);
        }

        public void SendMessage(string methodName, object value, SendMessageOptions options)
        {
            foreach (Component c in FakeComponents.ToArray())
                if (c is Behaviour b && !b.FakeDestroyed) FakeEngine.Call(b, methodName, value);
        }
    }

    public class Transform : Component
    {
        Vector3 _localPosition;
        Quaternion _localRotation = Quaternion.identity;
        Vector3 _localScale = Vector3.one;
        Transform _parent;
        readonly List<Transform> _children = new List<Transform>();

        public Vector3 localPosition { get => _localPosition; set { _localPosition = value; Changed(); } }
        public Quaternion localRotation { get => _localRotation; set { _localRotation = value; Changed(); } }
        public Vector3 localScale { get => _localScale; set { _localScale = value; Changed(); } }

        public Vector3 position
        {
            get => _parent == null ? _localPosition : _parent.TransformPoint(_localPosition);
            set { _localPosition = _parent == null ? value : _parent.InverseTransformPoint(value); Changed(); }
        }

        public Quaternion rotation
        {
            get => _parent == null ? _localRotation : _parent.rotation * _localRotation;
            set { _localRotation = _parent == null ? value : Quaternion.Inverse(_parent.rotation) * value; Changed(); }
        }

        public Transform parent
        {
            get => _parent;
            set
            {
                Vector3 p = position;
                Quaternion q = rotation;
                _parent?._children.Remove(this);
                _parent = value;
                value?._children.Add(this);
                position = p;
                rotation = q;
            }
        }

        public bool hasChanged { get; set; }

        public Matrix4x4 localToWorldMatrix => default;

        public Vector3 lossyScale
        {
            get
            {
                Vector3 s = _localScale;
                for (Transform t = _parent; t != null; t = t._parent) s = Vector3.Scale(s, t._localScale);
                return s;
            }
        }

        public void SetPositionAndRotation(Vector3 position, Quaternion rotation)
        {
            this.position = position;
            this.rotation = rotation;
        }

        public Vector3 TransformPoint(Vector3 position) => this.position + rotation * Vector3.Scale(lossyScale, position);
        public Vector3 TransformDirection(Vector3 direction) => rotation * direction;
        public Vector3 InverseTransformPoint(Vector3 position)
        {
            Vector3 local = Quaternion.Inverse(rotation) * (position - this.position);
            Vector3 s = lossyScale;
            return new Vector3(local.x / s.x, local.y / s.y, local.z / s.z);
        }
        public Vector3 InverseTransformDirection(Vector3 direction) => Quaternion.Inverse(rotation) * direction;

        // Unity: a change to a transform sets hasChanged on it and on every transform below it.
        void Changed()
        {
            hasChanged = true;
            foreach (Transform c in _children) c.Changed();
        }
    }

    public sealed class Mesh : Object
    {
        Vector3[] _vertices = Array.Empty<Vector3>();
        Vector3[] _normals = Array.Empty<Vector3>();
        int[] _triangles = Array.Empty<int>();

        public Mesh() { }
        public bool isReadable => true;
        public Vector3[] vertices { get => (Vector3[])_vertices.Clone(); set => _vertices = (Vector3[])value.Clone(); }
        public Vector3[] normals { get => (Vector3[])_normals.Clone(); set => _normals = (Vector3[])value.Clone(); }
        public int[] triangles { get => (int[])_triangles.Clone(); set => _triangles = (int[])value.Clone(); }
        // Unity copies the data into the mesh; the fake copies in place so that a test can measure allocations.
        public void SetVertices(Vector3[] inVertices) => CopyInto(ref _vertices, inVertices);
        public void SetNormals(Vector3[] inNormals) => CopyInto(ref _normals, inNormals);
        public void RecalculateBounds() { }
        public void MarkDynamic() { }

        static void CopyInto(ref Vector3[] into, Vector3[] from)
        {
            if (into.Length != from.Length) into = new Vector3[from.Length];
            Array.Copy(from, into, from.Length);
        }
    }

    public sealed class MeshFilter : Component
    {
        Mesh _mesh;
        public Mesh sharedMesh { get; set; }
        // Unity: reading mesh instantiates the shared mesh once and assigns the copy.
        public Mesh mesh
        {
            get
            {
                if (_mesh == null && sharedMesh != null)
                {
                    _mesh = new Mesh { name = sharedMesh.name + " Instance", vertices = sharedMesh.vertices, triangles = sharedMesh.triangles, normals = sharedMesh.normals };
                    sharedMesh = _mesh;
                }
                return _mesh;
            }
            set { _mesh = value; sharedMesh = value; }
        }
    }

    public struct Bounds
    {
        public Bounds(Vector3 center, Vector3 size) { this.center = center; this.size = size; }
        public Vector3 center { get; set; }
        public Vector3 size { get; set; }
    }

    public struct Ray
    {
        Vector3 _direction;
        public Ray(Vector3 origin, Vector3 direction) { this.origin = origin; _direction = direction.normalized; }
        public Vector3 origin { get; set; }
        public Vector3 direction { get => _direction; set => _direction = value.normalized; }
    }

    public struct Vector3
    {
        public float x, y, z;
        public Vector3(float x, float y, float z) { this.x = x; this.y = y; this.z = z; }
        public static Vector3 zero => default;
        public static Vector3 one => new Vector3(1, 1, 1);
        public static Vector3 up => new Vector3(0, 1, 0);
        public static Vector3 down => new Vector3(0, -1, 0);
        public static Vector3 right => new Vector3(1, 0, 0);
        public static Vector3 forward => new Vector3(0, 0, 1);
        public float magnitude => (float)Math.Sqrt(x * x + y * y + z * z);
        public Vector3 normalized { get { float m = magnitude; return m > 1e-5f ? this * (1f / m) : zero; } }
        public static Vector3 Cross(Vector3 a, Vector3 b) => new Vector3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
        public static float Dot(Vector3 lhs, Vector3 rhs) => lhs.x * rhs.x + lhs.y * rhs.y + lhs.z * rhs.z;
        public static float Distance(Vector3 a, Vector3 b) => (a - b).magnitude;
        public static Vector3 Scale(Vector3 a, Vector3 b) => new Vector3(a.x * b.x, a.y * b.y, a.z * b.z);
        public static Vector3 operator +(Vector3 a, Vector3 b) => new Vector3(a.x + b.x, a.y + b.y, a.z + b.z);
        public static Vector3 operator -(Vector3 a, Vector3 b) => new Vector3(a.x - b.x, a.y - b.y, a.z - b.z);
        public static Vector3 operator -(Vector3 a) => new Vector3(-a.x, -a.y, -a.z);
        public static Vector3 operator *(Vector3 a, float d) => new Vector3(a.x * d, a.y * d, a.z * d);
        // Unity compares with a tolerance of 1e-5 on the squared distance.
        public static bool operator ==(Vector3 lhs, Vector3 rhs) => (lhs - rhs).x * (lhs - rhs).x + (lhs - rhs).y * (lhs - rhs).y + (lhs - rhs).z * (lhs - rhs).z < 9.99999944E-11f;
        public static bool operator !=(Vector3 lhs, Vector3 rhs) => !(lhs == rhs);
        public override bool Equals(object other) => other is Vector3 v && x == v.x && y == v.y && z == v.z;
        public override int GetHashCode() => x.GetHashCode() ^ (y.GetHashCode() << 2) ^ (z.GetHashCode() >> 2);
        public override string ToString() => $"({x:F2}, {y:F2}, {z:F2})";
    }

    public struct Quaternion
    {
        public float x, y, z, w;
        public Quaternion(float x, float y, float z, float w) { this.x = x; this.y = y; this.z = z; this.w = w; }
        public static Quaternion identity => new Quaternion(0, 0, 0, 1);
        public static Quaternion AngleAxis(float angle, Vector3 axis)
        {
            Vector3 n = axis.normalized;
            double h = angle * Math.PI / 360.0;
            float s = (float)Math.Sin(h);
            return new Quaternion(n.x * s, n.y * s, n.z * s, (float)Math.Cos(h));
        }
        public static Quaternion Inverse(Quaternion q) => new Quaternion(-q.x, -q.y, -q.z, q.w);
        public static Quaternion operator *(Quaternion a, Quaternion b) => new Quaternion(
            a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y + a.y * b.w + a.z * b.x - a.x * b.z,
            a.w * b.z + a.z * b.w + a.x * b.y - a.y * b.x,
            a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z);
        public static Vector3 operator *(Quaternion rotation, Vector3 point)
        {
            var u = new Vector3(rotation.x, rotation.y, rotation.z);
            Vector3 t = Vector3.Cross(u, point) * 2f;
            return point + t * rotation.w + Vector3.Cross(u, t);
        }
    }

    public struct Matrix4x4
    {
        public static Matrix4x4 identity => default;
    }

    public struct Color
    {
        public Color(float r, float g, float b, float a) { }
        public static Color red => default;
    }

    public enum ForceMode { Force = 0, Acceleration = 5, Impulse = 1, VelocityChange = 2 }
    public enum SendMessageOptions { RequireReceiver = 0, DontRequireReceiver = 1 }

    public static class Time
    {
        public static float time => FakeEngine.Time;
        public static float fixedTime => FakeEngine.FixedTime;
        public static float fixedDeltaTime { get => FakeEngine.FixedDeltaTime; set => FakeEngine.FixedDeltaTime = value; }
    }

    public struct Mathf
    {
        public const float PI = 3.14159274F;
        public const float Infinity = float.PositiveInfinity;
        public static float Clamp01(float value) => value < 0f ? 0f : value > 1f ? 1f : value;
        public static float Clamp(float value, float min, float max) => value < min ? min : value > max ? max : value;
        public static int Clamp(int value, int min, int max) => value < min ? min : value > max ? max : value;
        public static float Max(float a, float b) => a > b ? a : b;
        public static float Sqrt(float f) => (float)Math.Sqrt(f);
    }

    public static class Application
    {
        public static bool isPlaying => FakeEngine.Playing;
    }

    public static class Gizmos
    {
        public static Color color { get; set; }
        public static Matrix4x4 matrix { get; set; }
        public static void DrawWireCube(Vector3 center, Vector3 size) { }
        public static void DrawWireSphere(Vector3 center, float radius) { }
        public static void DrawSphere(Vector3 center, float radius) { }
        public static void DrawLine(Vector3 from, Vector3 to) { }
    }

    [AttributeUsage(AttributeTargets.Field)] public sealed class TooltipAttribute : Attribute { public TooltipAttribute(string tooltip) { } }
    [AttributeUsage(AttributeTargets.Class)] public sealed class DefaultExecutionOrder : Attribute { public DefaultExecutionOrder(int order) { FakeOrder = order; } internal readonly int FakeOrder; }
    [AttributeUsage(AttributeTargets.Class)] public sealed class DisallowMultipleComponent : Attribute { }
    [AttributeUsage(AttributeTargets.Field)] public sealed class SerializeField : Attribute { }
    [AttributeUsage(AttributeTargets.Class, AllowMultiple = true)] public sealed class RequireComponent : Attribute { public RequireComponent(Type requiredComponent) { FakeType = requiredComponent; } internal readonly Type FakeType; }

    /// <summary>
    /// Not a Unity type: plays the stand-in engine for tests (frames with FixedUpdate, Update and
    /// LateUpdate in execution order, the clock, end-of-frame destroys, a fresh scene).
    /// </summary>
    public static class FakeEngine
    {
        internal static readonly List<GameObject> Objects = new List<GameObject>();
        static readonly List<Object> s_destroyQueue = new List<Object>();
        internal static float Time, FixedTime, FixedDeltaTime = 0.02f;
        internal static bool Playing;

        /// <summary>Forgets every object and resets the clock (one test, one scene).</summary>
        public static void NewScene(float fixedDeltaTime = 0.02f)
        {
            foreach (GameObject g in Objects.ToArray()) DestroyNow(g);
            Objects.Clear();
            s_destroyQueue.Clear();
            Time = FixedTime = 0;
            FixedDeltaTime = fixedDeltaTime;
            Playing = true;
        }

        /// <summary>One fixed step: FixedUpdate on every live behaviour by execution order, then the end-of-frame destroys.</summary>
        public static void FixedStep()
        {
            FixedTime += FixedDeltaTime;
            Time = FixedTime;
            Broadcast("FixedUpdate");
            FlushDestroys();
        }

        /// <summary>One rendered frame after the fixed steps: Update, then LateUpdate, then the destroys.</summary>
        public static void Frame()
        {
            Broadcast("Update");
            Broadcast("LateUpdate");
            FlushDestroys();
        }

        internal static T FindFirst<T>() where T : Object
        {
            foreach (GameObject g in Objects)
                if (g.FakeActive && !g.FakeDestroyed)
                    foreach (Component c in g.FakeComponents)
                        if (c is T t && !c.FakeDestroyed) return t;
            return null;
        }

        internal static void QueueDestroy(Object o)
        {
            if (o != null && !s_destroyQueue.Contains(o)) s_destroyQueue.Add(o);
        }

        static void FlushDestroys()
        {
            Object[] queue = s_destroyQueue.ToArray();
            s_destroyQueue.Clear();
            foreach (Object o in queue) DestroyNow(o);
        }

        static void DestroyNow(Object o)
        {
            if (ReferenceEquals(o, null) || o.FakeDestroyed) return;
            if (o is GameObject g)
            {
                foreach (Component c in g.FakeComponents.ToArray()) DestroyNow(c);
                g.FakeDestroyed = true;
                Objects.Remove(g);
                return;
            }
            if (o is Behaviour b)
            {
                if (b.FakeEnabledCalled) { b.FakeEnabledCalled = false; Call(b, "OnDisable"); }
                Call(b, "OnDestroy");
            }
            o.FakeDestroyed = true;
            if (o is Component comp) comp.gameObject.FakeComponents.Remove(comp);
        }

        // OnEnable when a behaviour becomes active and enabled, OnDisable when it stops being so.
        internal static void Refresh(Behaviour b)
        {
            bool live = b.isActiveAndEnabled;
            if (live && !b.FakeEnabledCalled) { b.FakeEnabledCalled = true; Call(b, "OnEnable"); }
            else if (!live && b.FakeEnabledCalled) { b.FakeEnabledCalled = false; Call(b, "OnDisable"); }
        }

        static void Broadcast(string message)
        {
            var behaviours = new List<Behaviour>();
            foreach (GameObject g in Objects.ToArray())
                foreach (Component c in g.FakeComponents)
                    if (c is Behaviour b && b.isActiveAndEnabled) behaviours.Add(b);
            behaviours.Sort((a, b) => Order(a).CompareTo(Order(b)));
            foreach (Behaviour b in behaviours)
                if (b.isActiveAndEnabled) Call(b, message);
        }

        static int Order(Behaviour b)
        {
            var o = b.GetType().GetCustomAttribute<DefaultExecutionOrder>(true);
            return o == null ? 0 : o.FakeOrder;
        }

        /// <summary>Calls a message method (any access) declared on the behaviour's type or a base, as Unity does.</summary>
        internal static void Call(Behaviour b, string method, object argument = null)
        {
            for (Type t = b.GetType(); t != null && t != typeof(Behaviour); t = t.BaseType)
            {
                MethodInfo m = t.GetMethod(method, BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.DeclaredOnly);
                if (m == null) continue;
                m.Invoke(b, m.GetParameters().Length == 0 ? null : new[] { argument });
                return;
            }
        }
    }
}

namespace UnityEditor
{
    [Flags]
    public enum GizmoType { Pickable = 1, NotInSelectionHierarchy = 2, NonSelected = 32, Selected = 4, Active = 8, InSelectionHierarchy = 16 }

    [AttributeUsage(AttributeTargets.Method)]
    public sealed class DrawGizmo : Attribute { public DrawGizmo(GizmoType gizmo) { } }
}
