// UnityEngine.Debug as the samples use it, for the stub compile only. The tool leaves this
// file out once Tests/UnityCompileCheck~/UnityEngineStubs.cs declares a Debug type itself.
// Signatures checked against UnityCsReference's Runtime/Export/Debug/Debug.bindings.cs (the
// Unity 6 copy; these three overloads are in 2021.3's scripting reference too).
namespace UnityEngine
{
    public class Debug
    {
        public static void Log(object message) { }
        public static void LogWarning(object message) { }
        public static void LogError(object message) { }
    }
}
