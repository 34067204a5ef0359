using System;
using System.Collections.Generic;

namespace Fulcrum.Components
{
    public sealed partial class PhysicsScene
    {
        readonly List<Joint> _joints = new List<Joint>();
        readonly HandleOwners<Joint> _jointOwners = new HandleOwners<Joint>();

        internal void RegisterJoint(Joint j)
        {
            if (!_joints.Contains(j)) _joints.Add(j);
        }

        internal void UnregisterJoint(Joint j) => _needsCompaction = true;

        internal void MapJoint(JointHandle handle, Joint j) => _jointOwners.Set(handle.Id, j);

        /// <summary>The joint component that owns <paramref name="handle"/>, or null.</summary>
        public Joint? GetJoint(JointHandle handle) => _jointOwners.Get(handle.Id);

        // Joints whose bodies appeared since (a connected entity activated later) get built;
        // those whose body went away are rebuilt when it comes back.
        void BuildPendingJoints()
        {
            for (int k = 0; k < _joints.Count; k++)
            {
                Joint j = _joints[k];
                if (!j.isDestroyed && !j.IsBuilt) j.TryBuild();
            }
        }

        // After the contact messages: each joint that broke in the step tells the behaviours on
        // its entity (OnJointBreak with the force that broke it), then goes at the end of the frame.
        void DispatchJointBreaks()
        {
            ReadOnlySpan<JointBreakEvent> breaks = _world.JointBreakEvents;
            if (breaks.Length == 0) return;
            try
            {
                _dispatching = "OnJointBreak";
                for (int k = 0; k < breaks.Length; k++)
                {
                    Joint? j = GetJoint(breaks[k].Joint);
                    if (j == null || j.isDestroyed) continue;
                    float force = breaks[k].Force.Length();
                    Entity e = j.entity;
                    List<Component> cs = e.Components;
                    for (int c = 0; c < cs.Count; c++)
                        if (cs[c] is Behaviour b && !b.isDestroyed && e.activeInHierarchy) b.SendJointBreak(force);
                    Destroy(j);
                }
            }
            finally
            {
                _dispatching = null;
            }
        }
    }
}
