namespace Fulcrum.Scenes
{
    /// <summary>The <c>type</c> of a scene joint (JSON: <c>ball</c>, <c>hinge</c>, <c>distance</c>, <c>fixed</c>, <c>prismatic</c>, <c>coneTwist</c>).</summary>
    public enum SceneJointType : byte
    {
        /// <summary>Anchors coincide; rotation free.</summary>
        Ball = 0,
        /// <summary>Anchors coincide and the axes stay aligned: one rotational freedom.</summary>
        Hinge = 1,
        /// <summary>The anchor distance stays within [minLength, maxLength] (or springs toward it).</summary>
        Distance = 2,
        /// <summary>No relative motion.</summary>
        Fixed = 3,
        /// <summary>Slides along one axis; no rotation.</summary>
        Prismatic = 4,
        /// <summary>A ball joint whose swing is limited to a cone and whose twist to a range.</summary>
        ConeTwist = 5,
    }
}
