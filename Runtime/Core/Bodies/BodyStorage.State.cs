namespace Fulcrum
{
    internal sealed partial class BodyStorage
    {
        /// <summary>Writes every per-slot array up to <see cref="SlotStorage.SlotCount"/> and the slot bookkeeping.</summary>
        public void Save(StateWriter w)
        {
            w.Section("BODY");
            _slots.Save(w);
            var columns = new ColumnWriter(w, SlotCount);
            Columns(ref columns);
        }

        /// <summary>Reads what <see cref="Save"/> wrote into a new storage at the saved capacity.</summary>
        public static BodyStorage Load(StateReader r)
        {
            r.Section("BODY");
            var b = new BodyStorage { _slots = SlotAllocator.Load(r, "bodies") };
            var columns = new ColumnReader(r, b.SlotCount, b._slots.Capacity);
            b.Columns(ref columns);
            return b;
        }

        // Every per-slot array once, in state order: Grow resizes, Save writes and Load reads this list.
        void Columns<TVisitor>(ref TVisitor v) where TVisitor : struct, IColumnVisitor
        {
            v.Column(ref Position, "body positions");
            v.Column(ref Rotation, "body rotations");
            v.Column(ref Center, "body centres");
            v.Column(ref LinearVelocity, "body linear velocities");
            v.Column(ref AngularVelocity, "body angular velocities");
            v.Column(ref InverseMass, "body inverse masses");
            v.Column(ref InverseInertiaWorld, "body world inverse inertias");
            v.Column(ref Type, "body types");
            v.Column(ref Awake, "body awake flags");
            v.Column(ref Force, "body forces");
            v.Column(ref Torque, "body torques");
            v.Column(ref InverseInertiaPrincipal, "body principal inverse inertias");
            v.Column(ref InertiaFrame, "body inertia frames");
            v.Column(ref LocalCenter, "body local centres");
            v.Column(ref Radius, "body radii");
            v.Column(ref LinearDamping, "body linear damping");
            v.Column(ref AngularDamping, "body angular damping");
            v.Column(ref GravityScale, "body gravity scales");
            v.Column(ref Locks, "body axis locks");
            v.Column(ref PreviousPosition, "body previous positions");
            v.Column(ref PreviousRotation, "body previous rotations");
            v.Column(ref StartLinearVelocity, "body step-start linear velocities");
            v.Column(ref StartAngularVelocity, "body step-start angular velocities");
            v.Column(ref Mass, "body masses");
            v.Column(ref InertiaLocal, "body local inertias");
            v.Column(ref MassOverride, "body mass overrides");
            v.Column(ref AllowSleep, "body sleep permissions");
            v.Column(ref Ccd, "body CCD flags");
            v.Column(ref SleepTime, "body sleep timers");
            v.Column(ref HasKinematicTarget, "body kinematic target flags");
            v.Column(ref VelocityFromTarget, "body target velocity flags");
            v.Column(ref TargetPosition, "body target positions");
            v.Column(ref TargetRotation, "body target rotations");
            v.Column(ref FirstShape, "body shape lists");
            v.Strings(ref Name, "body names");
            v.Column(ref UserData, "body user data");
        }
    }
}
