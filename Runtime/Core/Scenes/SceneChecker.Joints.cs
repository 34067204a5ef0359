using System.Collections.Generic;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// A joint: its bodies, anchors, axes and the limits, motors and springs of its kind.
    /// </summary>
    internal sealed partial class SceneChecker
    {
        void Joint(SceneJoint j, string path, HashSet<string> bodies)
        {
            if (j == null) { Error(path, "must not be null"); return; }
            if (j.Name != null && j.Name.Length == 0) Error(P(path, "name"), "must be a non-empty name (or left out)");
            if (j.BodyA == null && j.BodyB == null) Error(path, "bodyA and bodyB cannot both be the world (null)");
            if (j.BodyA != null && !Exists(j.BodyA, bodies)) Error(P(path, "bodyA"), $"no body named '{j.BodyA}'");
            if (j.BodyB != null && !Exists(j.BodyB, bodies)) Error(P(path, "bodyB"), $"no body named '{j.BodyB}'");
            if (j.BodyA != null && j.BodyA == j.BodyB) Error(P(path, "bodyB"), "a joint needs two different bodies");
            Coordinate(j.AnchorA, P(path, "anchorA"));
            Coordinate(j.AnchorB, P(path, "anchorB"));
            if (j.BreakForce is float force) Positive(force, P(path, "breakForce"));
            if (j.BreakTorque is float torque) Positive(torque, P(path, "breakTorque"));
            if (j.FrictionTorque is float friction) NonNegative(friction, P(path, "frictionTorque"));
            if (j is SceneAxisPairJoint axes)
            {
                Axis(axes.AxisA, P(path, "axisA"));
                Axis(axes.AxisB, P(path, "axisB"));
            }
            switch (j)
            {
                case SceneHingeJoint h:
                    if (h.LowerDeg is float lo) InRange(lo, -180, 180, P(path, "lowerDeg"));
                    if (h.UpperDeg is float hi) InRange(hi, -180, 180, P(path, "upperDeg"));
                    if (h.LowerDeg > h.UpperDeg) Error(P(path, "upperDeg"), $"must be >= lowerDeg ({F(h.LowerDeg!.Value)}), got {F(h.UpperDeg!.Value)}");
                    Finite(h.MotorSpeed, P(path, "motorSpeed"));
                    NonNegative(h.MaxMotorTorque, P(path, "maxMotorTorque"));
                    break;
                case SceneDistanceJoint d:
                    if (d.MinLength is float min) NonNegative(min, P(path, "minLength"));
                    if (d.MaxLength is float max) NonNegative(max, P(path, "maxLength"));
                    if (d.MinLength > d.MaxLength) Error(P(path, "maxLength"), $"must be >= minLength ({F(d.MinLength!.Value)}), got {F(d.MaxLength!.Value)}");
                    NonNegative(d.StiffnessHz, P(path, "stiffnessHz"));
                    NonNegative(d.Damping, P(path, "damping"));
                    break;
                case ScenePrismaticJoint p:
                    Axis(p.AxisA, P(path, "axisA"));
                    if (p.Lower is float l) Finite(l, P(path, "lower"));
                    if (p.Upper is float u) Finite(u, P(path, "upper"));
                    if (p.Lower > p.Upper) Error(P(path, "upper"), $"must be >= lower ({F(p.Lower!.Value)}), got {F(p.Upper!.Value)}");
                    break;
                case SceneConeTwistJoint c:
                    InRange(c.ConeDeg, 0, 180, P(path, "coneDeg"));
                    InRange(c.TwistDeg, 0, 180, P(path, "twistDeg"));
                    break;
            }
        }
    }
}
