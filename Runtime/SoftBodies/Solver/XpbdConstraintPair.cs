namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The two constraints of one element (deviatoric and hydrostatic) solved together as one
    /// 2x2 block rather than one after the other, so neither undoes the other within an
    /// iteration: the multiplier updates solve [s K + diag(alpha)] (dlD, dlH) = (rD, rH), where K
    /// is the 2x2 matrix of mass-weighted gradient dot products and alpha the time-scaled
    /// compliances.
    /// </summary>
    internal static class XpbdConstraintPair
    {
        /// <summary>
        /// Solves the 2x2 system by Cramer's rule; false (and no update) when it is degenerate.
        /// The matrix is s K + diag(alpha) with K positive semi-definite, so det &gt; 0 unless
        /// the element has collapsed.
        /// </summary>
        public static bool Solve(float a11, float a12, float a22, float rD, float rH, out float dlD, out float dlH)
        {
            float det = a11 * a22 - a12 * a12;
            if (!(det > 1e-30f * a11 * a22))
            {
                dlD = dlH = 0f;
                return false;
            }
            float invDet = 1f / det;
            dlD = (rD * a22 - rH * a12) * invDet;
            dlH = (a11 * rH - a12 * rD) * invDet;
            return true;
        }
    }
}
