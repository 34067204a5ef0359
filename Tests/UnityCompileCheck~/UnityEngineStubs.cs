// Stand-ins for the parts of UnityEngine and UnityEditor that Fulcrum.Unity and Fulcrum.Editor
// use, with Unity's names and signatures, so that `dotnet build` can type-check the adapters.
// Bodies do nothing. Never shipped: Unity does not import folders whose names end in '~'.
// Every member was checked against Unity's C# reference source (github.com/Unity-Technologies/
// UnityCsReference), branches 2021.3 (2021.3.58f1) and 6000.0 (6000.0.78f1): same name, static-ness,
// parameter and return types. Two differ by version and are used under #if: FindObjectOfType is
// obsolete from 2023.1 (FindAnyObjectByType replaces it; it exists from 2021.3.18).
// Members Unity has and these lack are simply not used by the adapters.
#nullable disable
#pragma warning disable CS0067, CS0626, CS1591
using System;

namespace UnityEngine
{
    public class Object
    {
        public string name { get; set; }
        public static T FindObjectOfType<T>() where T : Object => null;
        public static T FindAnyObjectByType<T>() where T : Object => null;
        public static void Destroy(Object obj) { }
    }

    public class Component : Object
    {
        public GameObject gameObject => null;
        public Transform transform => null;
        public T GetComponent<T>() => default;
        public T GetComponentInParent<T>() => default;
        public T[] GetComponents<T>() => Array.Empty<T>();
        public void GetComponents<T>(System.Collections.Generic.List<T> results) { }
        public void SendMessage(string methodName, object value, SendMessageOptions options) { }
    }

    public class Behaviour : Component
    {
        public bool enabled { get; set; }
        public bool isActiveAndEnabled => enabled;
    }

    public class MonoBehaviour : Behaviour { }

    public sealed class GameObject : Object
    {
        public GameObject(string name) { this.name = name; }
        public Transform transform => null;
        public int layer { get; set; }
        public T AddComponent<T>() where T : Component => null;
        public T GetComponent<T>() => default;
        public T[] GetComponents<T>() => Array.Empty<T>();
        public void GetComponents<T>(System.Collections.Generic.List<T> results) { }
        public void SendMessage(string methodName, object value, SendMessageOptions options) { }
    }

    public class Transform : Component
    {
        public Vector3 position { get; set; }
        public Quaternion rotation { get; set; }
        public Transform parent { get; set; }
        public bool hasChanged { get; set; }
        public Matrix4x4 localToWorldMatrix => default;
        public Vector3 lossyScale => default;
        public void SetPositionAndRotation(Vector3 position, Quaternion rotation) { }
        public Vector3 InverseTransformPoint(Vector3 position) => default;
        public Vector3 InverseTransformDirection(Vector3 direction) => default;
    }

    public sealed class Mesh : Object
    {
        public Mesh() { }
        public bool isReadable => true;
        public Vector3[] vertices { get => Array.Empty<Vector3>(); set { } }
        public int[] triangles { get => Array.Empty<int>(); set { } }
        public void SetVertices(Vector3[] inVertices) { }
        public void SetNormals(Vector3[] inNormals) { }
        public void RecalculateBounds() { }
        public void MarkDynamic() { }
    }

    public sealed class MeshFilter : Component
    {
        public Mesh sharedMesh { get; set; }
        public Mesh mesh { get; set; }
    }

    public struct Bounds
    {
        public Bounds(Vector3 center, Vector3 size) { }
    }

    public struct Ray
    {
        public Ray(Vector3 origin, Vector3 direction) { }
        public Vector3 origin { get => default; set { } }
        public Vector3 direction { get => default; set { } }
    }

    public struct Vector3
    {
        public float x, y, z;
        public Vector3(float x, float y, float z) { this.x = x; this.y = y; this.z = z; }
        public static Vector3 zero => default;
        public static Vector3 one => new Vector3(1, 1, 1);
        public static Vector3 up => new Vector3(0, 1, 0);
        public static Vector3 right => new Vector3(1, 0, 0);
        public static Vector3 forward => new Vector3(0, 0, 1);
        public Vector3 normalized => this;
        public static Vector3 Cross(Vector3 a, Vector3 b) => default;
        public static Vector3 operator +(Vector3 a, Vector3 b) => default;
        public static Vector3 operator -(Vector3 a, Vector3 b) => default;
        public static Vector3 operator -(Vector3 a) => default;
        public static Vector3 operator *(Vector3 a, float s) => default;
        public static bool operator ==(Vector3 a, Vector3 b) => false;
        public static bool operator !=(Vector3 a, Vector3 b) => true;
        public override bool Equals(object o) => false;
        public override int GetHashCode() => 0;
    }

    public struct Quaternion
    {
        public float x, y, z, w;
        public Quaternion(float x, float y, float z, float w) { this.x = x; this.y = y; this.z = z; this.w = w; }
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
        public static float time => 0;
        public static float fixedTime => 0;
        public static float fixedDeltaTime => 0.02f;
    }

    public struct Mathf
    {
        public const float PI = 3.14159274F;
        public const float Infinity = float.PositiveInfinity;
        public static float Clamp01(float value) => value;
        public static float Clamp(float value, float min, float max) => value;
        public static int Clamp(int value, int min, int max) => value;
        public static float Max(float a, float b) => a;
        public static float Sqrt(float f) => f;
    }

    public static class Application
    {
        public static bool isPlaying => false;
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
    [AttributeUsage(AttributeTargets.Class)] public sealed class DefaultExecutionOrder : Attribute { public DefaultExecutionOrder(int order) { } }
    [AttributeUsage(AttributeTargets.Class)] public sealed class DisallowMultipleComponent : Attribute { }
    [AttributeUsage(AttributeTargets.Class, AllowMultiple = true)] public sealed class RequireComponent : Attribute { public RequireComponent(Type type) { } }
}

namespace UnityEditor
{
    [Flags]
    public enum GizmoType { Pickable = 1, NotInSelectionHierarchy = 2, NonSelected = 32, Selected = 4, Active = 8, InSelectionHierarchy = 16 }

    [AttributeUsage(AttributeTargets.Method)]
    public sealed class DrawGizmo : Attribute { public DrawGizmo(GizmoType gizmo) { } }
}
