// UnityEngine.TextAsset as the Scenes sample uses it, for the stub compile only. The tool
// leaves this file out once Tests/UnityCompileCheck~/UnityEngineStubs.cs declares a
// TextAsset type itself. Signature as in Unity 2021.3's reference source
// (Runtime/Export/Scripting/TextAsset.cs).
namespace UnityEngine
{
    public class TextAsset : Object
    {
        public string text => "";
    }
}
