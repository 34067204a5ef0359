using System;
using System.Numerics;
using Fulcrum.Collision;

namespace Fulcrum.Dynamics
{
    internal sealed partial class SolverContext
    {
        // ---- constraint batches: colouring and preparing the step's contacts and joints ----

        /// <summary>
        /// Copies the bodies' state into the solver bodies and builds every constraint of the
        /// step: colours them, then prepares them in colour order. With <paramref name="wide"/>
        /// the four-point manifolds go to the SIMD path, prepared lane-wise straight from the
        /// manifolds, unless <paramref name="keepRows"/> asks for every manifold's scalar rows
        /// (PGS's position passes read them): the wide groups are then loaded from those.
        /// </summary>
        public void Prepare(IslandBuilder islands, bool wide = false, bool keepRows = false)
        {
            Bodies[0] = new SolverBody { DeltaRotation = Quaternion.Identity };
            RunGroups(GroupPass.LoadBodies, BodyCount - 1, MinBodyChunk);

            ref readonly WorldSettings set = ref _settings;
            float contactHertz = MathF.Min(set.ContactHertz, Softness.MaxStableHertz(_h));
            _contactStep = new ContactStep(_dt, _invH,
                Softness.Make(contactHertz, set.ContactDampingRatio, _h),
                Softness.Make(MathF.Min(2f * contactHertz, Softness.MaxStableHertz(_h)), set.ContactDampingRatio, _h),
                set.WarmStarting ? _h / _previousDt : 0f, set.BlockSolver,
                set.MaxContactPushSpeed, set.LinearSlop, set.RestitutionThreshold);

            _jointParameters = new JointSolver.StepParameters
            {
                Joint = Softness.Make(MathF.Min(set.JointHertz, Softness.MaxStableHertz(_h)), set.JointDampingRatio, _h).WithMaxBias(set.MaxJointCorrectionSpeed),
                H = _h,
                InvH = _invH,
                // Joints are projected fully in each position pass (Box2D v2.x); a fraction, as
                // for contacts, converges far too slowly along chains with large mass ratios.
                Beta = 1f,
                MaxCorrection = set.MaxJointCorrectionSpeed * _dt / Math.Max(1, set.PositionIterations),
            };

            // Colour every constraint in a fixed order: contacts, then joints.
            int nm = islands.ManifoldCount, nj = islands.JointCount;
            if (_color.Length < nm + nj) _color = new int[Math.Max(16, 2 * (nm + nj))];
            Array.Clear(_contactCursor, 0, Buckets);
            Array.Clear(_jointCursor, 0, Buckets);
            Array.Clear(_pointCursor, 0, Buckets);
            bool direct = BeginWide(wide, keepRows);
            for (int k = 0; k < nm; k++)
            {
                ref ContactManifold m = ref _manifolds[islands.Manifolds[k]];
                if (m.PointCount > ContactManifold.MaxPoints) m.PointCount = ContactManifold.MaxPoints;
                int a = IndexOf(m.BodyA), b = IndexOf(m.BodyB);
                int c = ConstraintColoring.Assign(_colorMask, a, Bodies[a].IsDynamic != 0, b, Bodies[b].IsDynamic != 0);
                if (direct && TakeWideCandidate(k, c, m, a, b)) continue;
                _color[k] = c;
                _contactCursor[c]++;
                _pointCursor[c] += m.PointCount;
            }
            for (int k = 0; k < nj; k++)
            {
                ref JointData j = ref _joints.Data[islands.Joints[k]];
                int a = IndexOf(j.BodyA), b = IndexOf(j.BodyB);
                int c = ConstraintColoring.Assign(_colorMask, a, Bodies[a].IsDynamic != 0, b, Bodies[b].IsDynamic != 0);
                _color[nm + k] = c;
                _jointCursor[c]++;
            }
            float warmContacts = _contactStep.WarmScale;
            HasRestitution = false;
            if (direct) PrepareWide(islands, warmContacts);
            // Prefix sums: bucket starts, then the counters become insertion cursors.
            int contacts = 0, joints = 0, points = 0;
            for (int c = 0; c < Buckets; c++)
            {
                _contactStart[c] = contacts;
                _jointStart[c] = joints;
                int nc = _contactCursor[c], njc = _jointCursor[c], np = _pointCursor[c];
                _contactCursor[c] = contacts;
                _jointCursor[c] = joints;
                _pointCursor[c] = points;
                contacts += nc;
                joints += njc;
                points += np;
            }
            _contactStart[Buckets] = contacts;
            _jointStart[Buckets] = joints;
            ContactCount = contacts;
            JointCount = joints;
            PointCount = points;
            if (Contacts.Length < contacts) Contacts = new ContactConstraint[Math.Max(16, contacts * 2)];
            if (Points.Length < points) Points = new ContactConstraintPoint[Math.Max(64, points * 2)];
            if (JointOrder.Length < joints) JointOrder = new int[Math.Max(16, joints * 2)];

            for (int k = 0; k < nm; k++)
            {
                int c = _color[k];
                if (c >= Buckets) continue;
                PrepareScalar(islands.Manifolds[k], c);
            }
            if (direct) PrepareRejected(contacts);
            else SplitWide(wide && WideContacts);
            float warmJoints = set.WarmStarting ? 1f : 0f;
            // A joint over the most any joint can carry over from the last (sub)step (see
            // JointSolver.RunsAway) is one of a set that contradict each other: every joint on
            // its bodies starts cold with it (one left warm would fling the body with the set's
            // whole cancelled impulse).
            if (nj > 0)
            {
                float mass = 0;
                for (int k = 1; k < BodyCount; k++)
                    if (Bodies[k].IsDynamic != 0) mass += 1f / Bodies[k].InverseMass;
                float maxJointImpulse = JointSolver.MaxWarmImpulse(mass, _h);
                if (_runaway.Length < BodyCount) _runaway = new bool[Bodies.Length];
                Array.Clear(_runaway, 0, BodyCount);
                for (int k = 0; k < nj; k++)
                {
                    ref JointData j = ref _joints.Data[islands.Joints[k]];
                    if (!JointSolver.RunsAway(j, maxJointImpulse)) continue;
                    _runaway[IndexOf(j.BodyA)] = true;
                    _runaway[IndexOf(j.BodyB)] = true;
                }
                _runaway[0] = false; // static bodies and the world are shared by every joint
            }
            for (int k = 0; k < nj; k++)
            {
                int slot = islands.Joints[k];
                int at = _jointCursor[_color[nm + k]]++;
                JointOrder[at] = slot;
                ref JointData j = ref _joints.Data[slot];
                j.SolverA = IndexOf(j.BodyA);
                j.SolverB = IndexOf(j.BodyB);
                bool drop = _runaway[j.SolverA] || _runaway[j.SolverB];
                JointSolver.Begin(ref j, _storage, _h, drop ? 0f : warmJoints);
                RunJoint(ref j, JointSolver.Pass.Prepare);
            }
        }

        // Copies the bodies [start, end) of the step into the solver bodies (Prepare).
        void LoadBodies(int start, int end)
        {
            BodyStorage s = _storage;
            Vector3 gravity = _settings.Gravity;
            for (int k = start; k < end; k++)
            {
                int i = BodySlot[k];
                bool dynamic = s.Type[i] == BodyType.Dynamic;
                ref SolverBody body = ref Bodies[k];
                body.LinearVelocity = s.LinearVelocity[i];
                body.AngularVelocity = s.AngularVelocity[i];
                body.InverseMass = dynamic ? s.InverseMass[i] : 0;
                body.InverseInertia = dynamic ? s.InverseInertiaWorld[i] : default;
                body.IsDynamic = dynamic ? SolverBody.DynamicFlags(s.Locks[i]) : 0;
                body.DeltaPosition = Vector3.Zero;
                body.DeltaRotation = Quaternion.Identity;
                _startCenter[k] = s.Center[i];
                _startRotation[k] = s.Rotation[i];
                _kick[k] = dynamic ? SubstepKick.Of(s, i, gravity, _h) : default;
                _colorMask[k] = 0;
            }
        }

        void PrepareScalar(int mi, int c)
        {
            ref ContactManifold m = ref _manifolds[mi];
            HasRestitution |= m.Restitution > 0;
            int at = _contactCursor[c]++;
            int firstPoint = _pointCursor[c];
            _pointCursor[c] += m.PointCount;
            ContactSolver.Prepare(ref Contacts[at], Points, firstPoint, ref m, mi, Bodies, IndexOf(m.BodyA), IndexOf(m.BodyB), _contactStep);
        }
    }
}
