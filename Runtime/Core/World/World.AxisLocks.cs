using System;
using Fulcrum.Dynamics;

namespace Fulcrum
{
    public sealed partial class World
    {
        /// <summary>
        /// Sets the world axes a body may not translate along or rotate about (see
        /// <see cref="AxisLocks"/>). The velocity components along newly locked axes are
        /// removed at once and the world inverse inertia is projected; the body wakes. Unknown
        /// bits throw <see cref="ArgumentException"/> before anything changes.
        /// </summary>
        public void SetAxisLocks(BodyHandle body, AxisLocks locks)
        {
            ThrowIfInStep();
            int i = Slot(body);
            CheckAxisLocks(locks, nameof(locks));
            BodyStorage b = Bodies;
            if (b.Locks[i] == locks) return;
            b.Locks[i] = locks;
            if (b.Type[i] != BodyType.Dynamic) return;
            b.LinearVelocity[i] = AxisLockMath.MaskLinear(b.LinearVelocity[i], locks);
            b.AngularVelocity[i] = AxisLockMath.MaskAngular(b.AngularVelocity[i], locks);
            b.UpdateWorldInertia(i);
            Wake(i);
        }

        /// <summary>The axis locks of a body (<see cref="BodyDef.Locks"/>).</summary>
        public AxisLocks GetAxisLocks(BodyHandle body) => Bodies.Locks[Slot(body)];

        internal static void CheckAxisLocks(AxisLocks locks, string name)
        {
            if ((locks & ~AxisLocks.All) != 0)
                throw new ArgumentException($"{name} has unknown bits 0x{(int)locks:X} (AxisLocks has LinearX/Y/Z and AngularX/Y/Z).", name);
        }
    }
}
