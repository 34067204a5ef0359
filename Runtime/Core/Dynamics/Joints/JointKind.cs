namespace Fulcrum
{
    /// <summary>The kinds of joint, in the world and in the scene model (<c>SceneJoint.Type</c>); the scene file names them in lower camel case (<c>ball</c>, <c>hinge</c>, <c>distance</c>, <c>fixed</c>, <c>prismatic</c>, <c>coneTwist</c>).</summary>
    public enum JointKind : byte
    {
        /// <summary>"ball": the anchors coincide; free rotation.</summary>
        Ball = 0,
        /// <summary>"hinge": the anchors coincide and the bodies turn about one axis, with optional limits, motor and spring.</summary>
        Hinge = 1,
        /// <summary>"distance": the anchors' distance stays within [min, max] (a rod, a rope), with an optional spring.</summary>
        Distance = 2,
        /// <summary>"fixed": no relative motion (a weld).</summary>
        Fixed = 3,
        /// <summary>"prismatic": the bodies slide along one axis without turning, with optional limits and motor.</summary>
        Prismatic = 4,
        /// <summary>"coneTwist": a ball joint whose swing stays in a cone and whose twist stays within limits (ragdolls).</summary>
        ConeTwist = 5,
    }
}
