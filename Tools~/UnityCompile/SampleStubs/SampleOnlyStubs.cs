// UnityEngine types that only the samples' MonoBehaviours use and that
// Tests/UnityCompileCheck~/UnityEngineStubs.cs does not declare (yet). Signatures as in
// Unity 2021.3's reference source (UnityCsReference: Runtime/Export/Debug/Debug.bindings.cs,
// Runtime/Export/Scripting/TextAsset.cs). When the shared stubs gain a type, delete it here
// (a duplicate fails the stub compile).
namespace UnityEngine
{
    public class Debug
    {
        public static void Log(object message) { }
        public static void LogWarning(object message) { }
        public static void LogError(object message) { }
    }

    public class TextAsset : Object
    {
        public string text => "";
    }
}
