namespace Fulcrum.Scenes
{
    /// <summary>
    /// The <c>mesh</c> of a soft body. One subclass per <see cref="SceneSoftMeshType"/>
    /// (<see cref="SceneSoftBox"/>, <see cref="SceneSoftSphere"/>, <see cref="SceneSoftCloth"/>, ...),
    /// each holding that kind's fields. Volume kinds become tetrahedra; <c>cloth</c> and
    /// <c>obj</c> become triangle shells.
    /// </summary>
    public abstract class SceneSoftMesh
    {
        /// <summary>The kind, written as the <c>type</c> field.</summary>
        public abstract SceneSoftMeshType Type { get; }

        /// <summary>True for the kinds that make a triangle shell (cloth, obj) rather than tetrahedra.</summary>
        public bool IsShell => Type == SceneSoftMeshType.Cloth || Type == SceneSoftMeshType.Obj;
    }
}
