using System;
using System.Numerics;
using Fulcrum.Collision;

namespace Fulcrum.Dynamics
{
    internal sealed partial class SolverContext
    {
        // ---- the SIMD contact path: every #if NET of the solver is in this file ----
        // On net10 the four-point manifolds of a colour go to ContactSolverWide in groups of
        // Vector<float>.Count; elsewhere (Unity's netstandard2.1 build) the stubs at the end
        // leave every contact to the scalar path, and the rest of SolverContext reads the same.

#if NET
        WideContact[] _wide = Array.Empty<WideContact>();
        WideImpact[] _wideImpact = Array.Empty<WideImpact>();
        int[] _wideManifold = Array.Empty<int>();
        int[] _rejected = Array.Empty<int>();
        readonly int[] _rejectedStart = new int[Buckets + 1];
        readonly int[] _wideCursor = new int[Buckets];
        int[] _wideBodies = Array.Empty<int>();
        int[] _wideSlots = Array.Empty<int>();
        int[] _wideSource = Array.Empty<int>();
        // The wide prepare's rejects, a lane-sized window per group, and how many each group has.
        int[] _groupRejects = Array.Empty<int>();
        int[] _groupRejectCount = Array.Empty<int>();

        void ReserveWide(int manifolds)
        {
            if (_rejected.Length < manifolds) _rejected = new int[manifolds];
            // Each colour's last group may be padded: at most one group per colour more.
            int width = ContactSolverWide.Width;
            int groups = (manifolds + width - 1) / width + Buckets;
            int lanes = groups * width;
            if (_wide.Length < groups)
            {
                _wide = new WideContact[groups];
                _wideImpact = new WideImpact[groups];
            }
            if (_wideManifold.Length < lanes) _wideManifold = new int[lanes];
            if (_wideBodies.Length < 2 * lanes) _wideBodies = new int[2 * lanes];
            if (_wideSlots.Length < 4 * lanes) _wideSlots = new int[4 * lanes];
            if (_wideSource.Length < lanes) _wideSource = new int[lanes];
            if (_groupRejects.Length < lanes) _groupRejects = new int[lanes];
            if (_groupRejectCount.Length < groups) _groupRejectCount = new int[groups];
        }

        // Whether this step prepares the wide candidates straight from their manifolds (the
        // block solver on, SIMD hardware, no scalar rows asked for); then clears their counts.
        bool BeginWide(bool wide, bool keepRows)
        {
            bool direct = wide && WideContacts && !keepRows && _settings.BlockSolver && Vector.IsHardwareAccelerated;
            if (direct) Array.Clear(_wideCursor, 0, Buckets);
            return direct;
        }

        // Marks manifold k of colour c (between solver bodies a and b) as a wide candidate (its
        // colour plus Buckets) when the wide path may take it.
        bool TakeWideCandidate(int k, int c, in ContactManifold m, int a, int b)
        {
            if (c >= ConstraintColoring.MaxColors || !ContactSolverWide.MayAccept(m) || HasLinearLocks(a, b)) return false;
            _color[k] = c + Buckets;
            _wideCursor[c]++;
            return true;
        }

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

        // The wide path's rejects, colour by colour, after that colour's other contacts; every
        // scalar contact is then in colour order already.
        void PrepareRejected(int contacts)
        {
            // The wide path's rejects, colour by colour, after that colour's other contacts.
            for (int c = 0; c < Buckets; c++)
                for (int r = _rejectedStart[c]; r < _rejectedStart[c + 1]; r++)
                    PrepareScalar(_rejected[r], c);
            if (_scalarContacts.Length < contacts) _scalarContacts = new int[Math.Max(16, 2 * contacts)];
            for (int k = 0; k < contacts; k++) _scalarContacts[k] = k;
            Array.Copy(_contactStart, _scalarStart, Buckets + 1);
        }

        // Sorts each colour's contacts into wide groups (those ContactSolverWide accepts, in
        // groups of Vector<float>.Count, the last one padded) and the scalar rest.
        void SplitWide(bool wide)
        {
            if (_scalarContacts.Length < ContactCount) _scalarContacts = new int[Math.Max(16, 2 * ContactCount)];
            int scalar = 0;
            _wideGroups = 0;
            int width = ContactSolverWide.Width;
            int lanes = 0;
            if (wide && _wideSource.Length < ContactCount + Buckets * width)
            {
                int n = 2 * ContactCount + Buckets * width;
                _wideSource = new int[n];
            }
            for (int c = 0; c < Buckets; c++)
            {
                _scalarStart[c] = scalar;
                _wideStart[c] = _wideGroups;
                for (int k = _contactStart[c], end = _contactStart[c + 1]; k < end; k++)
                {
                    if (wide && c < ConstraintColoring.MaxColors && ContactSolverWide.Accepts(Contacts[k])
                        && !HasLinearLocks(Contacts[k].BodyA, Contacts[k].BodyB))
                    {
                        _wideSource[lanes++] = k;
                        continue;
                    }
                    _scalarContacts[scalar++] = k;
                }
                // Close the colour's last group (padding lanes are -1).
                while (lanes % width != 0) _wideSource[lanes++] = -1;
                _wideGroups = lanes / width;
            }
            _scalarStart[Buckets] = scalar;
            _wideStart[Buckets] = _wideGroups;
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
        }

        // The lanes carry one inverse mass per body: a body with a locked translation axis has
        // three (AxisLocks), so its contacts take the scalar path, which is exact for them.
        // Rotation locks ride in the inverse inertia and stay wide.
        bool HasLinearLocks(int a, int b) => Bodies[a].HasLinearLocks || Bodies[b].HasLinearLocks;

        // The constraint indices of group g's used lanes.
        ReadOnlySpan<int> WideLanes(int g)
        {
            int width = ContactSolverWide.Width;
            var lanes = new ReadOnlySpan<int>(_wideSource, g * width, width);
            int used = 0;
            while (used < width && lanes[used] >= 0) used++;
            return lanes.Slice(0, used);
        }

        void AccumulateWide() => RunGroups(GroupPass.Accumulate, _wideGroups, 4 * MinGroupChunk);

        void StoreWide(float scale)
        {
            _groupJob.Scale = scale;
            RunGroups(GroupPass.StoreImpulses, _wideGroups, MinGroupChunk);
        }

        // One pass over the wide groups [start, end) of a colour's range (those below wideCount).
        void RunWide(ColorPass pass, int wideStart, int wideCount, int start, int end)
        {
            int wideEnd = Math.Min(end, wideCount);
            if (start < wideEnd)
            {
                int first = wideStart + start, last = wideStart + wideEnd;
                switch (pass)
                {
                    case ColorPass.WarmStart: ContactSolverWide.WarmStart(_wide, first, last, Bodies, _wideBodies); break;
                    case ColorPass.Solve: ContactSolverWide.Solve(_wide, _wideImpact, first, last, Bodies, _wideBodies, _contactStep, true); break;
                    case ColorPass.Relax: ContactSolverWide.Solve(_wide, _wideImpact, first, last, Bodies, _wideBodies, _contactStep, false); break;
                    case ColorPass.Restitution: ContactSolverWide.ApplyRestitution(_wide, _wideImpact, first, last, Bodies, _wideBodies, _contactStep.RestitutionThreshold); break;
                    case ColorPass.Approach: ContactSolverWide.RefreshApproach(_wide, _wideImpact, first, last, Bodies, _wideBodies); break;
                    default:
                        // The position pass needs only geometry, which the scalar constraints keep.
                        for (int g = first; g < last; g++)
                        {
                            ReadOnlySpan<int> lanes = WideLanes(g);
                            for (int lane = 0; lane < lanes.Length; lane++)
                                ContactPositionSolver.Solve(ref Contacts[lanes[lane]], Points, Bodies, _contactStep, _held[lanes[lane]], _settings.ShockDepth);
                        }
                        break;
                }
            }
        }
        // The wide groups' share of GroupJob (SolverContext.GroupJob.cs), one range of groups
        // each. Each group's rejects go to its own window of the scratch list; the caller gathers
        // them colour by colour in group order afterwards.
        bool PrepareWideGroups(int start, int end, float warmContacts)
        {
            int width = ContactSolverWide.Width;
            bool restitution = false;
            for (int g = start; g < end; g++)
            {
                int n = g * width;
                restitution |= ContactSolverWide.Prepare(_wide, _wideImpact, g, g + 1, _wideManifold, _wideBodies,
                    _wideSlots, _manifolds, Bodies, warmContacts, _groupRejects, ref n);
                _groupRejectCount[g] = n - g * width;
            }
            return restitution;
        }

        void AccumulateWideGroups(int start, int end)
        {
            for (int g = start; g < end; g++) ContactSolverWide.Accumulate(_wide[g], ref _wideImpact[g]);
        }

        void StoreWideGroups(int start, int end, float scale)
        {
            int width = ContactSolverWide.Width;
            for (int g = start; g < end; g++)
                ContactSolverWide.Store(_wide[g], _wideImpact[g], _wideSlots, _wideManifold, g * width, _manifolds, scale);
        }
#else
        bool PrepareWideGroups(int start, int end, float warmContacts) => false;

        void AccumulateWideGroups(int start, int end) { }

        void StoreWideGroups(int start, int end, float scale) { }

        void ReserveWide(int manifolds) { }

        bool BeginWide(bool wide, bool keepRows) => false;

        bool TakeWideCandidate(int k, int c, in ContactManifold m, int a, int b) => false;

        void PrepareWide(IslandBuilder islands, float warmContacts) { }

        void PrepareRejected(int contacts) { }

        // Every contact is scalar: each colour's contacts in order.
        void SplitWide(bool wide)
        {
            if (_scalarContacts.Length < ContactCount) _scalarContacts = new int[Math.Max(16, 2 * ContactCount)];
            int scalar = 0;
            _wideGroups = 0;
            for (int c = 0; c < Buckets; c++)
            {
                _scalarStart[c] = scalar;
                _wideStart[c] = 0;
                for (int k = _contactStart[c], end = _contactStart[c + 1]; k < end; k++) _scalarContacts[scalar++] = k;
            }
            _scalarStart[Buckets] = scalar;
            _wideStart[Buckets] = 0;
        }

        void AccumulateWide() { }

        void StoreWide(float scale) { }

        void RunWide(ColorPass pass, int wideStart, int wideCount, int start, int end) { }
#endif
    }
}
