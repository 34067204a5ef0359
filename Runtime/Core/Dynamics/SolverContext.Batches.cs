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
            BodyStorage s = _storage;
            Bodies[0] = new SolverBody { DeltaRotation = Quaternion.Identity };
            for (int k = 1; k < BodyCount; k++)
            {
                int i = BodySlot[k];
                bool dynamic = s.Type[i] == BodyType.Dynamic;
                ref SolverBody body = ref Bodies[k];
                body.LinearVelocity = s.LinearVelocity[i];
                body.AngularVelocity = s.AngularVelocity[i];
                body.InverseMass = dynamic ? s.InverseMass[i] : 0;
                body.InverseInertia = dynamic ? s.InverseInertiaWorld[i] : default;
                body.IsDynamic = dynamic ? 1 : 0;
                body.DeltaPosition = Vector3.Zero;
                body.DeltaRotation = Quaternion.Identity;
                _startCenter[k] = s.Center[i];
                _startRotation[k] = s.Rotation[i];
                _colorMask[k] = 0;
            }

            ref readonly WorldSettings set = ref _settings;
            float contactHertz = MathF.Min(set.ContactHertz, Softness.MaxStableHertz(_h));
            _contactSoftness = Softness.Make(contactHertz, set.ContactDampingRatio, _h);
            _fixedSoftness = Softness.Make(MathF.Min(2f * contactHertz, Softness.MaxStableHertz(_h)), set.ContactDampingRatio, _h);

            _jointParameters = new JointSolver.StepParameters
            {
                Joint = Softness.Make(MathF.Min(set.JointHertz, Softness.MaxStableHertz(_h)), set.JointDampingRatio, _h).WithMaxBias(set.MaxJointCorrectionSpeed),
                H = _h,
                InvH = _invH,
                // Joints are projected fully in each position pass (Box2D v2.x); a fraction, as
                // for contacts, converges far too slowly along chains with large mass ratios.
                Beta = 1f,
            };

            // Colour every constraint in a fixed order: contacts, then joints.
            int nm = islands.ManifoldCount, nj = islands.JointCount;
            if (_color.Length < nm + nj) _color = new int[Math.Max(16, 2 * (nm + nj))];
            Array.Clear(_contactCursor, 0, Buckets);
            Array.Clear(_jointCursor, 0, Buckets);
            Array.Clear(_pointCursor, 0, Buckets);
#if NET
            bool direct = wide && WideContacts && !keepRows && _settings.BlockSolver && Vector.IsHardwareAccelerated;
            if (direct) Array.Clear(_wideCursor, 0, Buckets);
#endif
            for (int k = 0; k < nm; k++)
            {
                ref ContactManifold m = ref _manifolds[islands.Manifolds[k]];
                if (m.PointCount > ContactManifold.MaxPoints) m.PointCount = ContactManifold.MaxPoints;
                int a = IndexOf(m.BodyA), b = IndexOf(m.BodyB);
                int c = ConstraintColoring.Assign(_colorMask, a, Bodies[a].IsDynamic != 0, b, Bodies[b].IsDynamic != 0);
#if NET
                if (direct && c < ConstraintColoring.MaxColors && ContactSolverWide.MayAccept(m))
                {
                    // A wide candidate: its colour plus Buckets marks it.
                    _color[k] = c + Buckets;
                    _wideCursor[c]++;
                    continue;
                }
#endif
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
            float warmContacts = set.WarmStarting ? _h / _previousDt : 0f;
            HasRestitution = false;
#if NET
            if (direct) PrepareWide(islands, warmContacts);
#endif
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

            bool block = set.BlockSolver;
            for (int k = 0; k < nm; k++)
            {
                int c = _color[k];
                if (c >= Buckets) continue;
                PrepareScalar(islands.Manifolds[k], c, warmContacts, block);
            }
#if NET
            if (direct)
            {
                // The wide path's rejects, colour by colour, after that colour's other contacts.
                for (int c = 0; c < Buckets; c++)
                    for (int r = _rejectedStart[c]; r < _rejectedStart[c + 1]; r++)
                        PrepareScalar(_rejected[r], c, warmContacts, block);
                if (_scalarContacts.Length < contacts) _scalarContacts = new int[Math.Max(16, 2 * contacts)];
                for (int k = 0; k < contacts; k++) _scalarContacts[k] = k;
                Array.Copy(_contactStart, _scalarStart, Buckets + 1);
            }
            else
#endif
            SplitWide(wide && WideContacts);
            float warmJoints = set.WarmStarting ? 1f : 0f;
            for (int k = 0; k < nj; k++)
            {
                int slot = islands.Joints[k];
                int at = _jointCursor[_color[nm + k]]++;
                JointOrder[at] = slot;
                ref JointData j = ref _joints.Data[slot];
                j.SolverA = IndexOf(j.BodyA);
                j.SolverB = IndexOf(j.BodyB);
                JointSolver.Begin(ref j, _storage, _h, warmJoints);
                RunJoint(ref j, JointSolver.Pass.Prepare);
            }
        }

        void PrepareScalar(int mi, int c, float warmContacts, bool block)
        {
            ref ContactManifold m = ref _manifolds[mi];
            HasRestitution |= m.Restitution > 0;
            int at = _contactCursor[c]++;
            int firstPoint = _pointCursor[c];
            _pointCursor[c] += m.PointCount;
            ContactSolver.Prepare(ref Contacts[at], Points, firstPoint, ref m, mi, Bodies, IndexOf(m.BodyA), IndexOf(m.BodyB),
                _contactSoftness, _fixedSoftness, warmContacts, block);
        }

#if NET
        // The wide candidates (colour + Buckets in _color) into lanes, colour by colour, each
        // colour's last group padded; then prepared lane-wise. Rejected lanes are counted into
        // their colour's scalar contacts.
        void PrepareWide(IslandBuilder islands, float warmContacts)
        {
            int width = ContactSolverWide.Width;
            int groups = 0;
            for (int c = 0; c < Buckets; c++)
            {
                int count = _wideCursor[c];
                _wideStart[c] = groups;
                _wideCursor[c] = groups * width;
                groups += (count + width - 1) / width;
            }
            _wideStart[Buckets] = groups;
            _wideGroups = groups;
            int lanes = groups * width;
            int nm = islands.ManifoldCount;
            if (_wide.Length < groups)
            {
                _wide = new WideContact[2 * groups];
                _wideImpact = new WideImpact[2 * groups];
            }
            if (_wideManifold.Length < lanes)
            {
                _wideManifold = new int[2 * lanes];
                _wideBodies = new int[4 * lanes];
                _wideSlots = new int[8 * lanes];
            }
            if (_rejected.Length < nm) _rejected = new int[Math.Max(16, 2 * nm)];
            if (_groupRejects.Length < lanes)
            {
                _groupRejects = new int[2 * lanes];
                _groupRejectCount = new int[2 * groups];
            }
            Array.Fill(_wideManifold, -1, 0, lanes);
            Array.Clear(_wideBodies, 0, 2 * lanes);
            for (int k = 0; k < nm; k++)
            {
                int c = _color[k] - Buckets;
                if (c < 0) continue;
                int lane = _wideCursor[c]++;
                int mi = islands.Manifolds[k];
                ref ContactManifold m = ref _manifolds[mi];
                _wideManifold[lane] = mi;
                _wideBodies[2 * lane] = IndexOf(m.BodyA);
                _wideBodies[2 * lane + 1] = IndexOf(m.BodyB);
            }
            // Every group prepares on its own, split between threads (GroupJob); the rejects
            // are then gathered colour by colour in group order, as one serial loop lists them.
            _groupJob.WarmContacts = warmContacts;
            _groupJob.Restitution = false;
            RunGroups(GroupPass.PrepareWide, groups, MinGroupChunk);
            HasRestitution |= _groupJob.Restitution;
            int rejected = 0;
            for (int c = 0; c < Buckets; c++)
            {
                _rejectedStart[c] = rejected;
                for (int g = _wideStart[c]; g < _wideStart[c + 1]; g++)
                    for (int r = 0; r < _groupRejectCount[g]; r++)
                    {
                        _rejected[rejected++] = _groupRejects[g * width + r];
                        _contactCursor[c]++;
                        _pointCursor[c] += ContactManifold.MaxPoints;
                    }
            }
            _rejectedStart[Buckets] = rejected;
        }
#endif

        // Sorts each colour's contacts into wide groups (those ContactSolverWide accepts, in
        // groups of Vector<float>.Count, the last one padded) and the scalar rest.
        void SplitWide(bool wide)
        {
            if (_scalarContacts.Length < ContactCount) _scalarContacts = new int[Math.Max(16, 2 * ContactCount)];
            int scalar = 0;
            _wideGroups = 0;
#if NET
            int width = ContactSolverWide.Width;
            int lanes = 0;
            if (wide && _wideSource.Length < ContactCount + Buckets * width)
            {
                int n = 2 * ContactCount + Buckets * width;
                _wideSource = new int[n];
            }
#else
            wide = false;
#endif
            for (int c = 0; c < Buckets; c++)
            {
                _scalarStart[c] = scalar;
                _wideStart[c] = _wideGroups;
                for (int k = _contactStart[c], end = _contactStart[c + 1]; k < end; k++)
                {
#if NET
                    if (wide && c < ConstraintColoring.MaxColors && ContactSolverWide.Accepts(Contacts[k]))
                    {
                        _wideSource[lanes++] = k;
                        continue;
                    }
#endif
                    _scalarContacts[scalar++] = k;
                }
#if NET
                // Close the colour's last group (padding lanes are -1).
                while (lanes % width != 0) _wideSource[lanes++] = -1;
                _wideGroups = lanes / width;
#endif
            }
            _scalarStart[Buckets] = scalar;
            _wideStart[Buckets] = _wideGroups;
#if NET
            if (_wideGroups == 0) return;
            if (_wide.Length < _wideGroups)
            {
                _wide = new WideContact[2 * _wideGroups];
                _wideImpact = new WideImpact[2 * _wideGroups];
                _wideManifold = new int[2 * _wideGroups * width];
                _wideBodies = new int[2 * 2 * _wideGroups * width];
                _wideSlots = new int[2 * 4 * _wideGroups * width];
            }
            for (int g = 0; g < _wideGroups; g++)
            {
                ReadOnlySpan<int> used = WideLanes(g);
                ContactSolverWide.Load(ref _wide[g], ref _wideImpact[g], _wideBodies, g * width, used, Contacts, Points, _manifolds, _wideSlots);
                for (int lane = 0; lane < width; lane++)
                    _wideManifold[g * width + lane] = lane < used.Length ? Contacts[used[lane]].Manifold : -1;
            }
#endif
        }

#if NET
        // The constraint indices of group g's used lanes.
        ReadOnlySpan<int> WideLanes(int g)
        {
            int width = ContactSolverWide.Width;
            var lanes = new ReadOnlySpan<int>(_wideSource, g * width, width);
            int used = 0;
            while (used < width && lanes[used] >= 0) used++;
            return lanes.Slice(0, used);
        }
#endif
    }
}
