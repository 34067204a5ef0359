using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The rigid motion that best fits a motion field of point masses (mass-weighted least
    /// squares): the mean motion and the rotation omega = I^-1 sum m r x (d - mean) about the
    /// centre of mass, I the points' inertia there. Of displacements it is the rigid part of a
    /// step, of velocities the body's linear and angular velocity (the residual then carries no
    /// momentum and no angular momentum).
    /// </summary>
    internal static class RigidFit
    {
        /// <summary>
        /// Fits <paramref name="motion"/> at points <paramref name="at"/> of masses
        /// <paramref name="mass"/>, counting only points with a non-zero <paramref name="weight"/>
        /// (all of them when it is null). False when they have no mass (everything zero), or when
        /// the rotation is not finite (points on a line: the centre and mean are set, omega is zero).
        /// </summary>
        public static bool Fit(Vector3[] at, Vector3[] motion, float[] mass, float[]? weight, int n,
            out Vector3 centre, out Vector3 mean, out Vector3 omega)
        {
            centre = mean = omega = Vector3.Zero;
            double total = 0;
            Vector3 c = Vector3.Zero, d = Vector3.Zero;
            for (int i = 0; i < n; i++)
            {
                if (weight != null && weight[i] == 0f) continue;
                total += mass[i];
                c += mass[i] * at[i];
                d += mass[i] * motion[i];
            }
            if (!(total > 0)) return false;
            c /= (float)total;
            d /= (float)total;
            double lx = 0, ly = 0, lz = 0, xx = 0, yy = 0, zz = 0, xy = 0, xz = 0, yz = 0;
            for (int i = 0; i < n; i++)
            {
                if (weight != null && weight[i] == 0f) continue;
                Vector3 r = at[i] - c, u = motion[i] - d;
                double m = mass[i];
                lx += m * (r.Y * u.Z - r.Z * u.Y);
                ly += m * (r.Z * u.X - r.X * u.Z);
                lz += m * (r.X * u.Y - r.Y * u.X);
                xx += m * r.X * r.X; yy += m * r.Y * r.Y; zz += m * r.Z * r.Z;
                xy += m * r.X * r.Y; xz += m * r.X * r.Z; yz += m * r.Y * r.Z;
            }
            var inertia = new Mat3(
                new Vector3((float)(yy + zz), (float)-xy, (float)-xz),
                new Vector3((float)-xy, (float)(xx + zz), (float)-yz),
                new Vector3((float)-xz, (float)-yz, (float)(xx + yy)));
            Vector3 w = inertia.Inverse() * new Vector3((float)lx, (float)ly, (float)lz);
            centre = c;
            mean = d;
            if (!Validate.IsFinite(w)) return false;
            omega = w;
            return true;
        }
    }
}
