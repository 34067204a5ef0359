using System;

namespace Fulcrum
{
    public sealed partial class World
    {
        /// <summary>
        /// Changes a body between static, kinematic and dynamic (Unity's isKinematic toggles
        /// dynamic and kinematic). Mass is recomputed from the shapes (an explicit
        /// <see cref="SetMassProperties"/> is dropped: set it again); a body that stops moving
        /// loses its velocity. A change to or from static re-registers the shapes with the
        /// broad phase, whose static and moving sets differ.
        /// </summary>
        public void SetBodyType(BodyHandle body, BodyType type)
        {
            ThrowIfInStep();
            int i = Slot(body);
            if (type != BodyType.Static && type != BodyType.Kinematic && type != BodyType.Dynamic)
                throw new ArgumentException($"type must be Static, Kinematic or Dynamic, got {type}.", nameof(type));
            BodyStorage b = Bodies;
            BodyType old = b.Type[i];
            if (old == type) return;
            if (type == BodyType.Dynamic && b.MassOverride[i] >= 0)
            {
                // A static body's shapes were never weighed: check the mass they give before
                // anything changes (a huge dense static box would become an infinite mass).
                MassProperties m = ShapeMass(i);
                if (m.Mass > 0 || !float.IsFinite(m.Mass))
                {
                    if (b.MassOverride[i] == 0) Limits.CheckMass(m.Mass, "type (the body's mass from its shapes)");
                    if (!float.IsFinite(m.Mass) || !m.Inertia.IsFinite)
                        throw new ArgumentException($"type: {Describe(i)}'s shapes give mass properties that overflow (mass {m.Mass:G} kg); it cannot become dynamic.", nameof(type));
                }
            }
            bool staticChanges = (old == BodyType.Static) != (type == BodyType.Static);
            if (staticChanges)
                for (int s = b.FirstShape[i]; s >= 0; s = Shapes.NextInBody[s]) OnShapeRemoved(s);
            b.Type[i] = type;
            if (type == BodyType.Static)
            {
                b.LinearVelocity[i] = default;
                b.AngularVelocity[i] = default;
                b.Awake[i] = false;
            }
            else Wake(i);
            b.HasKinematicTarget[i] = false;
            b.VelocityFromTarget[i] = false;
            b.Force[i] = default;
            b.Torque[i] = default;
            if (b.MassOverride[i] < 0) b.MassOverride[i] = 0;
            UpdateMassProperties(i);
            if (staticChanges)
                for (int s = b.FirstShape[i]; s >= 0; s = Shapes.NextInBody[s]) OnShapeAdded(s);
        }
    }
}
