// UnityEngine.TextAsset as the Scenes sample uses it, for the stub compile only. The tool
// leaves this file out once Tests/UnityCompileCheck~/UnityEngineStubs.cs declares a
// TextAsset type itself. Checked against UnityCsReference's Runtime/Export/Scripting/TextAsset.cs
// (the Unity 6 copy: a partial class deriving from Object; text is read-only).
namespace UnityEngine
{
    public class TextAsset : Object
    {
        public string text => "";
    }
}
