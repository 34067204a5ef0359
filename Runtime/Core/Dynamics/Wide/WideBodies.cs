#if NET
using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Gathers solver bodies into <see cref="BodyLanes"/> and scatters them back: with the 4x4
    /// transposes of <see cref="SolverBodyLanes"/> where AVX gives eight lanes, lane by lane
    /// otherwise (the same values either way). A group's lane i holds the bodies
    /// laneBodies[2 (groupOffset + i)] (A) and laneBodies[2 (groupOffset + i) + 1] (B).
    /// </summary>
    internal static class WideBodies
    {
        /// <summary>
        /// Reads the two bodies of each lane of the group at <paramref name="groupOffset"/> into
        /// <paramref name="l"/>: velocities, inverse masses and flags always, inverse inertias
        /// with <paramref name="inertia"/>, the motion since the step began with <paramref name="motion"/>.
        /// </summary>
        public static void Gather(SolverBody[] bodies, int[] laneBodies, int groupOffset, ref BodyLanes l, bool inertia, bool motion)
        {
            if (SolverBodyLanes.IsSupported)
            {
                GatherSide(bodies, laneBodies, 2 * groupOffset, inertia, motion, out l.VA, out l.InvMassA, out l.WA, out l.FlagA, out l.IA, out l.DpA, out l.DThetaA);
                GatherSide(bodies, laneBodies, 2 * groupOffset + 1, inertia, motion, out l.VB, out l.InvMassB, out l.WB, out l.FlagB, out l.IB, out l.DpB, out l.DThetaB);
                return;
            }
            int width = Vector<float>.Count;
            for (int lane = 0; lane < width; lane++)
            {
                ref SolverBody a = ref bodies[laneBodies[2 * (groupOffset + lane)]];
                ref SolverBody b = ref bodies[laneBodies[2 * (groupOffset + lane) + 1]];
                l.VA.Set(lane, a.LinearVelocity);
                l.WA.Set(lane, a.AngularVelocity);
                l.VB.Set(lane, b.LinearVelocity);
                l.WB.Set(lane, b.AngularVelocity);
                WideVector3.Lane(ref l.InvMassA, lane) = a.InverseMass;
                WideVector3.Lane(ref l.InvMassB, lane) = b.InverseMass;
                WideVector3.Lane(ref l.FlagA, lane) = BitConverter.Int32BitsToSingle(a.IsDynamic);
                WideVector3.Lane(ref l.FlagB, lane) = BitConverter.Int32BitsToSingle(b.IsDynamic);
                if (inertia)
                {
                    l.IA.Set(lane, a.InverseInertia);
                    l.IB.Set(lane, b.InverseInertia);
                }
                if (!motion) continue;
                l.DpA.Set(lane, a.DeltaPosition);
                l.DpB.Set(lane, b.DeltaPosition);
                l.DThetaA.Set(lane, a.DeltaAngle);
                l.DThetaB.Set(lane, b.DeltaAngle);
            }
        }

        // One side (A: at = 2 groupOffset, B: at + 1) of the eight lanes, by transposes.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void GatherSide(SolverBody[] bodies, int[] laneBodies, int at, bool inertia, bool motion,
            out WideVector3 v, out Vector<float> invMass, out WideVector3 w, out Vector<float> flag, out WideMatrix3 ii, out WideVector3 dp, out WideVector3 dTheta)
        {
            ref float b0 = ref SolverBodyLanes.Body(bodies, laneBodies, at);
            ref float b1 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 2);
            ref float b2 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 4);
            ref float b3 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 6);
            ref float b4 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 8);
            ref float b5 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 10);
            ref float b6 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 12);
            ref float b7 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 14);
            SolverBodyLanes.Load(ref b0, ref b1, ref b2, ref b3, ref b4, ref b5, ref b6, ref b7, SolverBodyLanes.Linear,
                out Vector<float> vx, out Vector<float> vy, out Vector<float> vz, out invMass);
            SolverBodyLanes.Load(ref b0, ref b1, ref b2, ref b3, ref b4, ref b5, ref b6, ref b7, SolverBodyLanes.Angular,
                out Vector<float> wx, out Vector<float> wy, out Vector<float> wz, out flag);
            v = new WideVector3 { X = vx, Y = vy, Z = vz };
            w = new WideVector3 { X = wx, Y = wy, Z = wz };
            Vector<float> c2z = default, px = default, py = default, pz = default;
            if (inertia || motion)
                SolverBodyLanes.Load(ref b0, ref b1, ref b2, ref b3, ref b4, ref b5, ref b6, ref b7, SolverBodyLanes.Displacement,
                    out c2z, out px, out py, out pz);
            if (inertia)
            {
                SolverBodyLanes.Load(ref b0, ref b1, ref b2, ref b3, ref b4, ref b5, ref b6, ref b7, SolverBodyLanes.Inertia,
                    out Vector<float> c0x, out Vector<float> c0y, out Vector<float> c0z, out Vector<float> c1x);
                SolverBodyLanes.Load(ref b0, ref b1, ref b2, ref b3, ref b4, ref b5, ref b6, ref b7, SolverBodyLanes.Inertia + 4,
                    out Vector<float> c1y, out Vector<float> c1z, out Vector<float> c2x, out Vector<float> c2y);
                ii = new WideMatrix3
                {
                    C0 = new WideVector3 { X = c0x, Y = c0y, Z = c0z },
                    C1 = new WideVector3 { X = c1x, Y = c1y, Z = c1z },
                    C2 = new WideVector3 { X = c2x, Y = c2y, Z = c2z },
                };
            }
            else ii = default;
            if (!motion)
            {
                dp = default;
                dTheta = default;
                return;
            }
            SolverBodyLanes.Load(ref b0, ref b1, ref b2, ref b3, ref b4, ref b5, ref b6, ref b7, SolverBodyLanes.Rotation,
                out Vector<float> qx, out Vector<float> qy, out Vector<float> qz, out Vector<float> qw);
            dp = new WideVector3 { X = px, Y = py, Z = pz };
            // SolverBody.DeltaAngle, lane by lane: 2 x the vector part, sign chosen by w.
            Vector<float> twice = WideVector3.Select(Vector.LessThan(qw, Vector<float>.Zero), new Vector<float>(-2f), new Vector<float>(2f));
            dTheta = new WideVector3 { X = qx * twice, Y = qy * twice, Z = qz * twice };
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void ScatterSide(SolverBody[] bodies, int[] laneBodies, int at, in WideVector3 v, Vector<float> invMass, in WideVector3 w, Vector<float> flag)
        {
            // Only dynamic bodies are written (the flag is the angular block's fourth float).
            int write = (int)Vector256.ExtractMostSignificantBits(
                ~Vector256.Equals(Vector.AsVectorInt32(flag).AsVector256(), Vector256<int>.Zero));
            if (write == 0) return;
            ref float b0 = ref SolverBodyLanes.Body(bodies, laneBodies, at);
            ref float b1 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 2);
            ref float b2 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 4);
            ref float b3 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 6);
            ref float b4 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 8);
            ref float b5 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 10);
            ref float b6 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 12);
            ref float b7 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 14);
            SolverBodyLanes.Store(ref b0, ref b1, ref b2, ref b3, ref b4, ref b5, ref b6, ref b7, write, SolverBodyLanes.Linear, v.X, v.Y, v.Z, invMass);
            SolverBodyLanes.Store(ref b0, ref b1, ref b2, ref b3, ref b4, ref b5, ref b6, ref b7, write, SolverBodyLanes.Angular, w.X, w.Y, w.Z, flag);
        }

        /// <summary>Writes the lanes' velocities back into the dynamic bodies of the group at <paramref name="groupOffset"/>.</summary>
        public static void Scatter(SolverBody[] bodies, int[] laneBodies, int groupOffset, ref BodyLanes l)
        {
            if (SolverBodyLanes.IsSupported)
            {
                ScatterSide(bodies, laneBodies, 2 * groupOffset, l.VA, l.InvMassA, l.WA, l.FlagA);
                ScatterSide(bodies, laneBodies, 2 * groupOffset + 1, l.VB, l.InvMassB, l.WB, l.FlagB);
                return;
            }
            int width = Vector<float>.Count;
            for (int lane = 0; lane < width; lane++)
            {
                bodies[laneBodies[2 * (groupOffset + lane)]].StoreVelocities(l.VA.Get(lane), l.WA.Get(lane));
                bodies[laneBodies[2 * (groupOffset + lane) + 1]].StoreVelocities(l.VB.Get(lane), l.WB.Get(lane));
            }
        }
    }
}
#endif
