namespace Fulcrum
{
    internal sealed partial class BodyStorage
    {
        /// <summary>Writes every per-slot array up to <see cref="SlotStorage.SlotCount"/> and the slot bookkeeping.</summary>
        public void Save(StateWriter w)
        {
            w.Section("BODY");
            _slots.Save(w);
            int n = SlotCount;
            w.WriteArray(Position, n);
            w.WriteArray(Rotation, n);
            w.WriteArray(Center, n);
            w.WriteArray(LinearVelocity, n);
            w.WriteArray(AngularVelocity, n);
            w.WriteArray(InverseMass, n);
            w.WriteArray(InverseInertiaWorld, n);
            w.WriteArray(Type, n);
            w.WriteArray(Awake, n);
            w.WriteArray(Force, n);
            w.WriteArray(Torque, n);
            w.WriteArray(InverseInertiaPrincipal, n);
            w.WriteArray(InertiaFrame, n);
            w.WriteArray(LocalCenter, n);
            w.WriteArray(Radius, n);
            w.WriteArray(LinearDamping, n);
            w.WriteArray(AngularDamping, n);
            w.WriteArray(GravityScale, n);
            w.WriteArray(Locks, n);
            w.WriteArray(PreviousPosition, n);
            w.WriteArray(PreviousRotation, n);
            w.WriteArray(StartLinearVelocity, n);
            w.WriteArray(StartAngularVelocity, n);
            w.WriteArray(Mass, n);
            w.WriteArray(InertiaLocal, n);
            w.WriteArray(MassOverride, n);
            w.WriteArray(AllowSleep, n);
            w.WriteArray(Ccd, n);
            w.WriteArray(SleepTime, n);
            w.WriteArray(HasKinematicTarget, n);
            w.WriteArray(VelocityFromTarget, n);
            w.WriteArray(TargetPosition, n);
            w.WriteArray(TargetRotation, n);
            w.WriteArray(FirstShape, n);
            w.WriteStrings(Name, n);
            w.WriteArray(UserData, n);
        }

        /// <summary>Reads what <see cref="Save"/> wrote into a new storage at the saved capacity.</summary>
        public static BodyStorage Load(StateReader r)
        {
            r.Section("BODY");
            var b = new BodyStorage { _slots = SlotAllocator.Load(r, "bodies") };
            int n = b.SlotCount, c = b._slots.Capacity;
            b.Position = r.ReadSlots<System.Numerics.Vector3>("body positions", n, c);
            b.Rotation = r.ReadSlots<System.Numerics.Quaternion>("body rotations", n, c);
            b.Center = r.ReadSlots<System.Numerics.Vector3>("body centres", n, c);
            b.LinearVelocity = r.ReadSlots<System.Numerics.Vector3>("body linear velocities", n, c);
            b.AngularVelocity = r.ReadSlots<System.Numerics.Vector3>("body angular velocities", n, c);
            b.InverseMass = r.ReadSlots<float>("body inverse masses", n, c);
            b.InverseInertiaWorld = r.ReadSlots<Mathematics.Mat3>("body world inverse inertias", n, c);
            b.Type = r.ReadSlots<BodyType>("body types", n, c);
            b.Awake = r.ReadSlots<bool>("body awake flags", n, c);
            b.Force = r.ReadSlots<System.Numerics.Vector3>("body forces", n, c);
            b.Torque = r.ReadSlots<System.Numerics.Vector3>("body torques", n, c);
            b.InverseInertiaPrincipal = r.ReadSlots<System.Numerics.Vector3>("body principal inverse inertias", n, c);
            b.InertiaFrame = r.ReadSlots<System.Numerics.Quaternion>("body inertia frames", n, c);
            b.LocalCenter = r.ReadSlots<System.Numerics.Vector3>("body local centres", n, c);
            b.Radius = r.ReadSlots<float>("body radii", n, c);
            b.LinearDamping = r.ReadSlots<float>("body linear damping", n, c);
            b.AngularDamping = r.ReadSlots<float>("body angular damping", n, c);
            b.GravityScale = r.ReadSlots<float>("body gravity scales", n, c);
            b.Locks = r.ReadSlots<AxisLocks>("body axis locks", n, c);
            b.PreviousPosition = r.ReadSlots<System.Numerics.Vector3>("body previous positions", n, c);
            b.PreviousRotation = r.ReadSlots<System.Numerics.Quaternion>("body previous rotations", n, c);
            b.StartLinearVelocity = r.ReadSlots<System.Numerics.Vector3>("body step-start linear velocities", n, c);
            b.StartAngularVelocity = r.ReadSlots<System.Numerics.Vector3>("body step-start angular velocities", n, c);
            b.Mass = r.ReadSlots<float>("body masses", n, c);
            b.InertiaLocal = r.ReadSlots<Mathematics.Mat3>("body local inertias", n, c);
            b.MassOverride = r.ReadSlots<float>("body mass overrides", n, c);
            b.AllowSleep = r.ReadSlots<bool>("body sleep permissions", n, c);
            b.Ccd = r.ReadSlots<bool>("body CCD flags", n, c);
            b.SleepTime = r.ReadSlots<float>("body sleep timers", n, c);
            b.HasKinematicTarget = r.ReadSlots<bool>("body kinematic target flags", n, c);
            b.VelocityFromTarget = r.ReadSlots<bool>("body target velocity flags", n, c);
            b.TargetPosition = r.ReadSlots<System.Numerics.Vector3>("body target positions", n, c);
            b.TargetRotation = r.ReadSlots<System.Numerics.Quaternion>("body target rotations", n, c);
            b.FirstShape = r.ReadSlots<int>("body shape lists", n, c);
            b.Name = r.ReadStringSlots("body names", n, c);
            b.UserData = r.ReadSlots<ulong>("body user data", n, c);
            return b;
        }
    }
}
