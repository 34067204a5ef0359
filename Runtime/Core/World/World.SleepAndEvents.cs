using System;
using Fulcrum.Collision;
using Fulcrum.Dynamics;

namespace Fulcrum
{
    public sealed partial class World
    {
        /// <summary>
        /// <see cref="StepStage.SleepAndEvents"/>, the last stage: joints whose force or torque
        /// went over their threshold in the solve break (once, reported in
        /// <see cref="JointBreakEvents"/>); rest timers advance and resting islands fall asleep; each
        /// updated contact's touching state (and each sensor's overlap) becomes begin, persist or
        /// end events, after the ends of contacts removed between steps. Reads: the step's joint
        /// list and their stress, body velocities, the manifolds with the solver's impulses, the
        /// contacts' flags, the step's End events of contacts destroyed by the narrow phase.
        /// Writes: joints' broken flags and the break list, body sleep timers and awake flags,
        /// the islands' sleeping rings, the contacts' touching flags and <see cref="ContactEvents"/>.
        /// </summary>
        void SleepAndEvents(float dt)
        {
            CollectBrokenJoints();
            UpdateSleep(dt);
            PublishEvents();
        }

        // After the solve: joints whose force or torque went over the threshold break, once.
        void CollectBrokenJoints()
        {
            for (int k = 0; k < _islands.JointCount; k++)
            {
                int slot = _islands.Joints[k];
                ref JointData j = ref Joints.Data[slot];
                if (j.Broken || !(j.Stress > 1f)) continue;
                j.Broken = true;
                if (_jointBreakCount == _jointBreaks.Length) Array.Resize(ref _jointBreaks, _jointBreaks.Length * 2);
                _jointBreaks[_jointBreakCount++] = new JointBreakEvent
                {
                    Joint = new JointHandle(slot, Joints.Generation[slot], Id),
                    BodyA = j.BodyA < 0 ? BodyHandle.None : new BodyHandle(j.BodyA, Bodies.Generation[j.BodyA], Id),
                    BodyB = j.BodyB < 0 ? BodyHandle.None : new BodyHandle(j.BodyB, Bodies.Generation[j.BodyB], Id),
                    Force = j.Force,
                    Torque = j.Torque,
                    Stress = j.Stress,
                    UserData = j.UserData,
                };
            }
        }

        // Rest timers, then resting islands fall asleep.
        void UpdateSleep(float dt)
        {
            ContactManifold[] manifolds = StepManifolds();
            _islands.UpdateSleep(Bodies, manifolds, Joints, _settings, dt);
        }

        // Copies the solver's impulses back to the persistent contacts, then turns each awake
        // contact's touching state (and each sensor's overlap) into begin/persist/end events.
        void PublishEvents()
        {
            _queryBoundsStale = true;
            _eventCount = 0;
            for (int i = 0; i < _removalEventCount; i++) AppendEvent(_removalEvents[i]);
            _removalEventCount = 0;

            ContactGraph g = ContactGraph;
            float slop = _settings.LinearSlop;
            for (int k = 0; k < g.DenseCount; k++)
            {
                int c = g.Dense[k];
                ref Contact ct = ref g.Contacts[c];
                if ((ct.Flags & ContactFlags.Updated) == 0) continue;
                bool was = (ct.Flags & ContactFlags.Touching) != 0;
                bool now = (ct.Flags & ContactFlags.Sensor) != 0
                    ? (ct.Flags & ContactFlags.Overlapping) != 0
                    : IsTouching(ref ct, slop);
                if (now) ct.Flags |= ContactFlags.Touching;
                else ct.Flags &= ~ContactFlags.Touching;
                if (now) AddStepEvent(c, was ? ContactEventKind.Persist : ContactEventKind.Begin);
                else if (was) AddStepEvent(c, ContactEventKind.End);
            }

            int n = _stepEventCount;
            for (int i = 0; i < n; i++) _stepEventOrder[i] = i;
            _eventOrder.Sort(_stepEventKeys, _stepEventOrder, n);
            for (int i = 0; i < n; i++) AppendEvent(_stepEvents[_stepEventOrder[i]]);
            _stepEventCount = 0;
        }

        // Touching: a point within the linear slop, or one the solver pushed on (a
        // speculative point that stopped a fast body counts as a hit).
        bool IsTouching(ref Contact ct, float slop)
        {
            ContactGraph g = ContactGraph;
            for (int m = ct.FirstManifold; m >= 0; m = g.ManifoldNext[m])
            {
                ref ContactManifold mf = ref g.Manifolds[m];
                for (int i = 0; i < mf.PointCount; i++)
                {
                    ref ContactPoint p = ref ContactManifold.Point(ref mf, i);
                    if (p.Separation <= slop || p.NormalImpulse > 0) return true;
                }
            }
            return false;
        }
    }
}
