using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    internal sealed partial class NarrowPhase
    {
        // Manifold reuse, after Jolt's body-pair cache: when the pair function runs, each
        // point is also stored as its two surface points in the shapes' own frames, with the
        // normal in A's frame and B's pose relative to A. While B has moved less than
        // ManifoldReuseDistance and ManifoldReuseAngle relative to A *since that run* (the
        // reference is not updated on reuse, so the error cannot accumulate), the points are
        // carried rigidly with the shapes instead of colliding again. A box resting on a
        // box then costs a few rotations instead of a separating-axis test, a clip and a
        // reduction; a moving pair moves more than a millimetre a step and collides as before.

        // True when contact ct's stored manifolds may stand in for the pair function this
        // step. Pure: the parallel narrow phase asks it too.
        bool CanReuseManifolds(in Contact ct, float speculative, in Pose poseA, in Pose poseB)
        {
            if ((ct.Flags & ContactFlags.Reusable) == 0) return false;
            // The stored points were filtered by the speculative distance of their run; a
            // point dropped then could be needed now only if the bound grew. A tenth of the
            // base margin of growth cannot make a dropped point (gap > base) close in this step.
            if (speculative > ct.ReuseSpeculative + 0.1f * _in.SpeculativeBase) return false;
            bool fromB = (ct.Flags & ContactFlags.ReuseFromB) != 0;
            Vector3 position;
            Quaternion rotation;
            if (fromB) RelativePose(poseB, poseA, out position, out rotation);
            else RelativePose(poseA, poseB, out position, out rotation);
            float d = _in.ReuseDistance;
            float moved = Vector3.DistanceSquared(position, ct.ReusePosition);
            if (moved > d * d) return false;
            // |cos(half the angle between the two relative rotations)|.
            float cosHalf = MathF.Abs(Quaternion.Dot(rotation, ct.ReuseRotation));
            if (cosHalf < _reuseCosHalfAngle) return false;
            // Whatever the angle allows, the smaller shape's farthest point (the chord 2 R
            // sin(angle / 2)) plus the shift must stay within half the speculative margin: a
            // corner that was beyond the margin when the manifold was made, and so is not in
            // it, cannot have come down to touch (a long plank tilting 2 degrees would swing
            // its far end 14 cm).
            float sinHalf = MathF.Sqrt(MathF.Max(0f, 1f - cosHalf * cosHalf));
            float radius = fromB ? _in.ShapeRadius[ct.ShapeA] : _in.ShapeRadius[ct.ShapeB];
            return MathF.Sqrt(moved) + 2f * radius * sinHalf <= 0.5f * _in.SpeculativeBase;
        }

        bool ReuseEnabled => _in.ReuseDistance > 0 && _in.ReuseAngle > 0;

        // cos(ManifoldReuseAngle / 2), refreshed at the start of each narrow phase.
        float _reuseCosHalfAngle = 1;

        static void RelativePose(in Pose a, in Pose b, out Vector3 position, out Quaternion rotation)
        {
            Quaternion inverseA = Quaternion.Conjugate(a.Rotation);
            position = Vector3.Transform(b.Position - a.Position, inverseA);
            rotation = inverseA * b.Rotation;
        }

        // Stores the manifolds just written by WriteManifolds in the shapes' frames.
        void RememberManifolds(ref Contact ct, float speculative, in Pose poseA, in Pose poseB)
        {
            ContactGraph g = Graph;
            Mat3 ra = Mat3.FromQuaternion(poseA.Rotation), rb = Mat3.FromQuaternion(poseB.Rotation);
            Vector3 d = poseB.Position - poseA.Position;
            for (int m = ct.FirstManifold; m >= 0; m = g.ManifoldNext[m])
            {
                ref ContactManifold mf = ref g.Manifolds[m];
                Vector3 n = mf.Normal;
                g.LocalNormal[m] = ra.TransposeMultiply(n);
                Vector3 carriedNormal = ra * g.LocalNormal[m];
                for (int i = 0; i < mf.PointCount; i++)
                {
                    ref ContactPoint cp = ref ContactManifold.Point(ref mf, i);
                    // Position is midway between the surfaces, Separation the gap along n. Both
                    // surface points are taken from the same offset r, so that whatever rounding
                    // r carries (world coordinates far from the origin round to micrometres)
                    // moves both alike.
                    Vector3 r = cp.Position - poseB.Position;
                    Vector3 half = 0.5f * cp.Separation * n;
                    Vector3 la = ra.TransposeMultiply(r + d - half), lb = rb.TransposeMultiply(r + half);
                    g.LocalPointA[4 * m + i] = la;
                    g.LocalPointB[4 * m + i] = lb;
                    // Rotating there and back rounds by about 1e-7 of the lever arm; the offset
                    // makes a reused separation start from exactly the pair function's answer.
                    Carry(carriedNormal, la, lb, ra, rb, d, out float carried);
                    g.SeparationOffset[4 * m + i] = cp.Separation - carried;
                }
            }
            // Track the smaller shape in the larger one's frame: a rotation then moves the
            // points that matter by at most the smaller radius times the angle.
            bool fromB = _in.ShapeRadius[ct.ShapeA] < _in.ShapeRadius[ct.ShapeB];
            if (fromB) RelativePose(poseB, poseA, out ct.ReusePosition, out ct.ReuseRotation);
            else RelativePose(poseA, poseB, out ct.ReusePosition, out ct.ReuseRotation);
            ct.ReuseSpeculative = speculative;
            ct.Flags = fromB ? ct.Flags | ContactFlags.Reusable | ContactFlags.ReuseFromB
                : (ct.Flags | ContactFlags.Reusable) & ~ContactFlags.ReuseFromB;
        }

        // Moves the stored points with the shapes' current poses and rewrites every point's
        // position, anchors and separation; impulses stay for warm starting (every point
        // persists). Returns false, with nothing lost (the impulses are untouched), when a
        // point drifted past the speculative distance: the caller then runs the pair function.
        // Writes only this contact's manifolds (the parallel pass runs it on the workers): the
        // caller adds the touching points and the deepest penetration to the step's figures
        // (CountReuse).
        bool ReuseManifolds(ref Contact ct, float speculative, in Pose poseA, in Pose poseB, out int touching, out float deepest)
        {
            ContactGraph g = Graph;
            ShapeStorage s = _in.Shapes;
            int sa = ct.ShapeA, sb = ct.ShapeB;
            float friction = Combine.Values(s.Friction[sa], s.FrictionCombine[sa], s.Friction[sb], s.FrictionCombine[sb]);
            float restitution = Combine.Values(s.Restitution[sa], s.RestitutionCombine[sa], s.Restitution[sb], s.RestitutionCombine[sb]);
            // Relative to B's origin throughout (see RememberManifolds on rounding).
            Mat3 ra = Mat3.FromQuaternion(poseA.Rotation), rb = Mat3.FromQuaternion(poseB.Rotation);
            Vector3 d = poseB.Position - poseA.Position;
            Vector3 toA = poseB.Position - _in.Bodies.Center[ct.BodyA], toB = poseB.Position - _in.Bodies.Center[ct.BodyB];
            float slop = _in.LinearSlop;
            Vector3 sum = Vector3.Zero;
            int total = 0;
            touching = 0;
            deepest = 0;
            for (int m = ct.FirstManifold; m >= 0; m = g.ManifoldNext[m])
            {
                ref ContactManifold mf = ref g.Manifolds[m];
                Vector3 n = ra * g.LocalNormal[m];
                mf.Normal = n;
                mf.Friction = friction;
                mf.Restitution = restitution;
                for (int i = 0; i < mf.PointCount; i++)
                {
                    ref ContactPoint cp = ref ContactManifold.Point(ref mf, i);
                    Vector3 x = Carry(n, g.LocalPointA[4 * m + i], g.LocalPointB[4 * m + i], ra, rb, d, out float separation);
                    separation += g.SeparationOffset[4 * m + i];
                    if (!(separation <= speculative)) return false;
                    cp.Position = poseB.Position + x;
                    cp.AnchorA = toA + x;
                    cp.AnchorB = toB + x;
                    cp.Separation = separation;
                    cp.RelativeNormalVelocity = 0;
                    cp.AppliedImpulse = 0;
                    cp.Persisted = true;
                    if (separation <= slop) touching++;
                    deepest = MathF.Max(deepest, -separation);
                    sum += x;
                    total++;
                }
            }
            if (total > 0)
            {
                Vector3 at = poseB.Position + sum / total;
                ct.RelativeVelocity = PointVelocity(ct.BodyB, at) - PointVelocity(ct.BodyA, at);
            }
            return true;
        }

        // A listed contact's share of the step's figures (serial: the fields are the stage's).
        void Count(int touching, float deepest)
        {
            Touching += touching;
            MaxPenetration = MathF.Max(MaxPenetration, deepest);
        }

        // After a contact's manifolds were rewritten from its pair function: its points are
        // remembered for reuse, unless it can approach by more than the reuse bound's half
        // margin in this step (it will have moved too far to reuse next step, and storing its
        // points would be wasted). Writes only this contact (the parallel pass runs it too).
        void FinishRewrite(ref Contact ct, float speculative, in Pose poseA, in Pose poseB)
        {
            if (ReuseEnabled && ct.ManifoldCount > 0 && speculative <= 1.5f * _in.SpeculativeBase)
                RememberManifolds(ref ct, speculative, poseA, poseB);
            else ct.Flags &= ~ContactFlags.Reusable;
        }

        // The two stored surface points carried with rotations ra and rb (B's origin d from
        // A's) and measured along the carried normal n: returns their midpoint relative to
        // B's origin.
        static Vector3 Carry(Vector3 n, Vector3 localA, Vector3 localB, in Mat3 ra, in Mat3 rb, Vector3 d, out float separation)
        {
            Vector3 pa = ra * localA - d;
            Vector3 pb = rb * localB;
            separation = Vector3.Dot(pb - pa, n);
            return 0.5f * (pa + pb);
        }
    }
}
