using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// How far one Newton step may go: a step whose largest move stands out from the rest is damped
    /// first, and no vertex moves more than a quarter of the shortest edge.
    /// </summary>
    internal sealed partial class ImplicitNewtonSolver
    {
        /// <summary>
        /// Levenberg-Marquardt damping of a step in which a few vertices would move further than
        /// the trust region (<c>_reach</c>), the longest move more than <see cref="Outlier"/> times
        /// the root mean square one: the inertia of every free vertex is raised by a factor
        /// 1 + lambda (lambda from largest / reach - 1, x4 per retry, at most four times) and the
        /// system is factored and solved again, so the step shrinks most in the modes that are
        /// soft, where scaling the whole step down does not. A nearly incompressible body's
        /// linear tets are stiff in volume and soft in shear: a bottom vertex of a nu = 0.4999
        /// slab, its neighbours pushed up 27 um out of the ground, got a Newton step of 9 cm
        /// sideways (the linear model's way to relieve the volume change); scaled to the trust
        /// region with the whole step it moved 2.5 cm, the slab's tets went to J 0.81 and 6e4 J
        /// of strain, and released over the next steps that energy threw an XPBD box resting on
        /// the slab about (its motion gained up to 663 J; none now). Not for a step whose moves
        /// are all long (a body striking the ground: its whole motion is the inertia the damping
        /// raises, and a nu = 0.49 cube thrown down at 10 m/s, damped at a ratio of 6, reached
        /// min J 0.39 instead of 0.72), nor with rigid bodies in the solve (their coupled system
        /// is solved once). False when the damped matrix cannot be factored (the step is skipped).
        /// </summary>
        bool Damp(SoftBody body, double invH2, ref double largest)
        {
            float[] m = body.M;
            double lambda = largest / _reach - 1, added = 0;
            for (int tries = 0; tries < 4 && largest > _reach; tries++, lambda *= 4)
            {
                Array.Copy(_saved, _matrix, _matrix.Length);
                for (int i = 0; i < _n; i++)
                {
                    if (_fixed[i]) continue;
                    int r = 3 * _order[i];
                    double d = (lambda - added) * m[i] * invH2;
                    for (int k = 0; k < 3; k++) At(r + k, r + k) += d;
                }
                added = lambda;
                if (!Factor()) return false;
                for (int k = 0; k < _dofs; k++) _rhs[k] = -_gradient[k];
                Solve(_rhs, 0);
                largest = LargestMove(out _);
            }
            return true;
        }

        /// <summary>How many times the root mean square move the longest must be for <see cref="Damp"/>: 8 (see there).</summary>
        const double Outlier = 8;

        // The longest move of a free vertex in the step direction (_rhs), and the root mean
        // square move, m.
        double LargestMove(out double rms)
        {
            double largest = 0, sum = 0;
            int count = 0;
            for (int i = 0; i < _n; i++)
            {
                if (_fixed[i]) continue;
                int r = 3 * _order[i];
                double move = _rhs[r] * _rhs[r] + _rhs[r + 1] * _rhs[r + 1] + _rhs[r + 2] * _rhs[r + 2];
                largest = Math.Max(largest, move);
                sum += move;
                count++;
            }
            rms = count > 0 ? Math.Sqrt(sum / count) : 0;
            return Math.Sqrt(largest);
        }
    }
}
