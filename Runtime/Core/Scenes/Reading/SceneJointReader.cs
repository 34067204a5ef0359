using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>Reads one entry of <c>joints</c>: the common fields, then those of its type.</summary>
    internal static class SceneJointReader
    {
        public static SceneJoint? Read(JsonValue v, SceneDiagnostics d)
        {
            JsonObjectReader? r = JsonObjectReader.OpenTyped(v, d, "a joint object", SceneNames.JointKinds, "joint type", out JointKind kind);
            if (r == null) return null;
            SceneJoint joint;
            switch (kind)
            {
                case JointKind.Ball:
                    joint = new SceneBallJoint();
                    break;
                case JointKind.Fixed:
                    joint = new SceneFixedJoint();
                    break;
                case JointKind.Hinge:
                    var hinge = WithAxes<SceneHingeJoint>(r);
                    hinge.LowerDeg = r.OptionalFloat("lowerDeg");
                    hinge.UpperDeg = r.OptionalFloat("upperDeg");
                    hinge.MotorSpeed = r.Float("motorSpeed", 0);
                    hinge.MaxMotorTorque = r.Float("maxMotorTorque", 0);
                    joint = hinge;
                    break;
                case JointKind.Distance:
                    joint = new SceneDistanceJoint
                    {
                        MinLength = r.OptionalFloat("minLength"),
                        MaxLength = r.OptionalFloat("maxLength"),
                        StiffnessHz = r.Float("stiffnessHz", 0),
                        Damping = r.Float("damping", 0),
                    };
                    break;
                case JointKind.Prismatic:
                    joint = new ScenePrismaticJoint
                    {
                        AxisA = r.Vector("axisA", Vector3.Zero, required: true),
                        Lower = r.OptionalFloat("lower"),
                        Upper = r.OptionalFloat("upper"),
                    };
                    break;
                default:
                    var cone = WithAxes<SceneConeTwistJoint>(r);
                    cone.ConeDeg = r.Float("coneDeg", 0, required: true);
                    cone.TwistDeg = r.Float("twistDeg", 0, required: true);
                    joint = cone;
                    break;
            }
            joint.Name = r.String("name");
            // bodyA and bodyB must be present; null names the world.
            r.Known("bodyA");
            r.Known("bodyB");
            joint.BodyA = BodyName(v, "bodyA", d);
            joint.BodyB = BodyName(v, "bodyB", d);
            joint.AnchorA = r.Vector("anchorA", Vector3.Zero);
            joint.AnchorB = r.Vector("anchorB", Vector3.Zero);
            joint.BreakForce = r.OptionalFloat("breakForce");
            joint.BreakTorque = r.OptionalFloat("breakTorque");
            joint.FrictionTorque = r.OptionalFloat("frictionTorque");
            r.Finish();
            return joint;
        }

        // A kind with an axis in each body's frame, its axisA and axisB read first (as for
        // every joint kind, the kind's own fields come before the common ones).
        static T WithAxes<T>(JsonObjectReader r) where T : SceneAxisPairJoint, new() => new T
        {
            AxisA = r.Vector("axisA", Vector3.Zero, required: true),
            AxisB = r.Vector("axisB", Vector3.Zero, required: true),
        };

        static string? BodyName(JsonValue joint, string key, SceneDiagnostics d)
        {
            JsonValue? v = joint[key];
            string path = JsonPath.Member(joint.Path, key);
            if (v == null)
            {
                d.Add(path, "missing required field (a body name, or null for the world)", joint);
                return null;
            }
            if (v.Kind == JsonKind.Null) return null;
            if (v.Kind == JsonKind.String) return v.AsString;
            d.Add(path, $"expected a body name or null, got {v.KindName}", v);
            return null;
        }
    }
}
