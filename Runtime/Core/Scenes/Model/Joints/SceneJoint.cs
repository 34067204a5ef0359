using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// An entry of <c>joints</c>: the fields every joint has. One subclass per
    /// <see cref="JointKind"/> adds that kind's fields. Joints are kept as data until the
    /// world has joints (see <see cref="SceneInstance.Joints"/>).
    /// </summary>
    public abstract class SceneJoint
    {
        /// <summary>The kind, written as the <c>type</c> field.</summary>
        public abstract JointKind Type { get; }

        /// <summary><c>name</c>: optional; unique among joints when given.</summary>
        public string? Name { get; set; }

        /// <summary><c>bodyA</c>: a body name, or null for the world. Not both bodies null.</summary>
        public string? BodyA { get; set; }

        /// <summary><c>bodyB</c>: a body name, or null for the world.</summary>
        public string? BodyB { get; set; }

        /// <summary><c>anchorA</c>: in body A's frame (world frame when A is the world), m. Default: 0.</summary>
        public Vector3 AnchorA { get; set; }

        /// <summary><c>anchorB</c>: in body B's frame (world frame when B is the world), m. Default: 0.</summary>
        public Vector3 AnchorB { get; set; }

        /// <summary><c>breakForce</c>: the joint breaks above this constraint force, N, &gt; 0; null: unbreakable.</summary>
        public float? BreakForce { get; set; }

        /// <summary><c>breakTorque</c>: the joint breaks above this constraint torque, N m, &gt; 0; null: unbreakable.</summary>
        public float? BreakTorque { get; set; }

        /// <summary><c>frictionTorque</c>: ball, hinge and coneTwist joint friction, N m, &gt;= 0; null: none (see <see cref="JointDef.FrictionTorque"/>).</summary>
        public float? FrictionTorque { get; set; }
    }
}
