using System;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// Turns one scene joint into a <see cref="JointDef"/>: the fields of DESIGN.md's joint
    /// entries map one to one (angles in degrees where the name ends in <c>Deg</c>, motor
    /// speeds in rad/s or m/s, lengths in metres); a field left out keeps the JointDef default.
    /// </summary>
    public static class SceneJointFactory
    {
        /// <summary>The definition of <paramref name="joint"/>, with body names resolved through <paramref name="body"/> (null = the world).</summary>
        public static JointDef Definition(SceneJoint joint, Func<string?, BodyHandle> body)
        {
            BodyHandle a = body(joint.BodyA), b = body(joint.BodyB);
            JointDef d;
            switch (joint)
            {
                case SceneBallJoint _:
                    d = JointDef.Ball(a, b, joint.AnchorA, joint.AnchorB);
                    break;
                case SceneHingeJoint h:
                    d = JointDef.Hinge(a, b, joint.AnchorA, joint.AnchorB, h.AxisA, h.AxisB);
                    if (h.LowerDeg is float lo) d.LowerDeg = lo;
                    if (h.UpperDeg is float hi) d.UpperDeg = hi;
                    d.MotorSpeed = h.MotorSpeed;
                    d.MaxMotorTorque = h.MaxMotorTorque;
                    break;
                case SceneDistanceJoint s:
                    d = JointDef.Distance(a, b, joint.AnchorA, joint.AnchorB, s.MinLength ?? -1, s.MaxLength ?? -1);
                    d.StiffnessHz = s.StiffnessHz;
                    d.Damping = s.Damping;
                    break;
                case SceneFixedJoint _:
                    d = JointDef.Fixed(a, b, joint.AnchorA, joint.AnchorB);
                    break;
                case ScenePrismaticJoint p:
                    d = JointDef.Prismatic(a, b, joint.AnchorA, joint.AnchorB, p.AxisA);
                    if (p.Lower is float pl) d.Lower = pl;
                    if (p.Upper is float pu) d.Upper = pu;
                    break;
                case SceneConeTwistJoint c:
                    d = JointDef.ConeTwist(a, b, joint.AnchorA, joint.AnchorB, c.AxisA, c.AxisB, c.ConeDeg, c.TwistDeg);
                    break;
                default:
                    throw new ArgumentException($"unknown joint type {joint.Type}.", nameof(joint));
            }
            if (joint.BreakForce is float f) d.BreakForce = f;
            if (joint.BreakTorque is float t) d.BreakTorque = t;
            if (joint.FrictionTorque is float friction) d.FrictionTorque = friction;
            d.Name = joint.Name;
            return d;
        }
    }
}
