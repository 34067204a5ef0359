using System;

namespace Fulcrum
{
    /// <summary>
    /// Degrees of freedom a dynamic body may not use, in WORLD axes (as Unity's
    /// RigidbodyConstraints and PhysX's PxRigidDynamicLockFlag; Jolt's EAllowedDOFs is the
    /// complement). The solver itself knows them: a locked translation axis has zero inverse
    /// mass along it (the inverse mass is per axis, m^-1 diag(allowed)), a locked rotation axis
    /// projects the world inverse inertia, I^-1' = P I^-1 P with P the projector on the free
    /// rotation axes, so contacts and joints see the reduced mobility in their effective masses
    /// and spend no impulse on motion the body cannot make. All three rotation axes locked is a
    /// body of infinite inertia. Static and kinematic bodies keep the flags but ignore them.
    /// </summary>
    /// <remarks>
    /// P I^-1 P is what PhysX and Jolt do. It is the ideal constraint when the locked axes are
    /// principal axes of the body (a 2D setup of boxes, spheres, capsules lying in the plane);
    /// for a body whose principal axes are tilted against the locks the ideal answer would be
    /// the inverse of P I P on the free axes, which is stiffer. Gyroscopic terms are dropped
    /// while any rotation axis is locked (exact when one or no rotation axis is free).
    /// </remarks>
    [Flags]
    public enum AxisLocks : byte
    {
        /// <summary>Free motion.</summary>
        None = 0,
        /// <summary>No translation of the centre of mass along world x.</summary>
        LinearX = 1,
        /// <summary>No translation of the centre of mass along world y.</summary>
        LinearY = 2,
        /// <summary>No translation of the centre of mass along world z.</summary>
        LinearZ = 4,
        /// <summary>No rotation about world x.</summary>
        AngularX = 8,
        /// <summary>No rotation about world y.</summary>
        AngularY = 16,
        /// <summary>No rotation about world z.</summary>
        AngularZ = 32,
        /// <summary>No translation at all.</summary>
        Linear = LinearX | LinearY | LinearZ,
        /// <summary>No rotation at all (infinite inertia).</summary>
        Angular = AngularX | AngularY | AngularZ,
        /// <summary>Neither translation nor rotation.</summary>
        All = Linear | Angular,
    }
}
