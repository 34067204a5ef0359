// UnityEngine.Debug as the samples use it, for the stub compile only. The tool leaves this
// file out once Tests/UnityCompileCheck~/UnityEngineStubs.cs declares a Debug type itself.
// Signatures as in Unity 2021.3's reference source (Runtime/Export/Debug/Debug.bindings.cs).
namespace UnityEngine
{
    public class Debug
    {
        public static void Log(object message) { }
        public static void LogWarning(object message) { }
        public static void LogError(object message) { }
    }
}
