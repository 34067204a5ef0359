using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Static friction inside the step: a vertex resting on an immovable shape is held across the
    /// normal by a spring to where it started the substep, part of G.
    /// </summary>
    internal sealed partial class ImplicitNewtonSolver
    {
        /// <summary>
        /// Holds vertex <paramref name="i"/> across <paramref name="n"/> by a spring of stiffness
        /// <paramref name="k"/> to its anchor, when it rests on an immovable shape
        /// (ShapeContactSolver.Sticks): the anchor is where it started the substep, carried by
        /// the shape's surface; the spring's energy is part of G. Static friction is then part of the
        /// step, as the ground springs are along the normal: the body hangs on its contacts
        /// inside the solve. Left to the contact pass after the step, friction pulled back only
        /// the touching vertices while the step had moved the whole body down the slope, the
        /// elastic pull between them read as more slip every substep, and a resting cube crept
        /// (E 1e8 Pa at 20 degrees, mu 0.5: 5.1 cm/s; nu 0.49 at 30 degrees, mu 0.7: 3.7 cm/s).
        /// </summary>
        void Stick(int i, int r, Vector3 n, Vector3 x, Vector3 anchor, double k)
        {
            Vector3 d = x - anchor;
            d -= Vector3.Dot(d, n) * n;
            for (int a = 0; a < 3; a++)
            {
                _rhs[r + a] -= k * Component(d, a);
                for (int b = 0; b <= a; b++) At(r + a, r + b) += k * ((a == b ? 1.0 : 0.0) - Component(n, a) * Component(n, b));
            }
            _stickVertex[_sticks] = i;
            _stickNormal[_sticks] = n;
            _stickAnchor[_sticks] = anchor;
            _stickStiffness[_sticks++] = k;
        }

        // The sticking springs' part of G: 1/2 k |(x - anchor) across the normal|^2.
        double StickEnergy(Vector3[] x)
        {
            double e = 0;
            for (int c = 0; c < _sticks; c++)
            {
                Vector3 d = x[_stickVertex[c]] - _stickAnchor[c];
                d -= Vector3.Dot(d, _stickNormal[c]) * _stickNormal[c];
                e += 0.5 * _stickStiffness[c] * d.LengthSquared();
            }
            return e;
        }

        /// <summary>
        /// The friction impulse (kg m) the sticking springs carried in the step, along the way they
        /// held their vertices back, for the patch's friction cone
        /// (<see cref="ShapeContactSolver.Stuck"/>, <see cref="ShapeContactSolver.Sticks"/>).
        /// </summary>
        void ReportSticks(SoftBody body, Vector3[] x, Vector3[] y, float h)
        {
            if (_sticks == 0) return;
            double h2 = (double)h * h;
            // The springs are stiff enough that their stretch is below the positions' float
            // resolution (a 27 kg cube resting on a slope: a few nanometres), so their own
            // measures read zero, or a whole step's friction on one vertex. What the body took
            // across the normal in the step is what they all held together: -sum_i m_i (x_i - y_i)
            // across their mean normal (the elements' forces cancel in it, as in ReportSupport),
            // spread over the held vertices by mass. Where the normals disagree (a body wedged
            // between two shapes) the springs' own measures stand.
            Vector3 normal = Vector3.Zero;
            double held = 0;
            float[] m = body.M;
            for (int c = 0; c < _sticks; c++)
            {
                normal += _stickNormal[c];
                held += m[_stickVertex[c]];
            }
            float agree = normal.Length();
            if (!(agree > 0.5f * _sticks) || !(held > 0))
            {
                for (int c = 0; c < _sticks; c++) body.Contacts.Stuck(_stickVertex[c], StickImpulse(c, x, h2));
                return;
            }
            normal /= agree;
            Vector3 total = Vector3.Zero;
            for (int i = 0; i < _n; i++) if (!_fixed[i]) total -= m[i] * (x[i] - y[i]);
            total -= Vector3.Dot(total, normal) * normal;
            for (int c = 0; c < _sticks; c++)
            {
                int i = _stickVertex[c];
                body.Contacts.Stuck(i, (float)(m[i] / held) * total);
            }
        }

        Vector3 StickImpulse(int c, Vector3[] x, double h2)
        {
            Vector3 d = x[_stickVertex[c]] - _stickAnchor[c];
            d -= Vector3.Dot(d, _stickNormal[c]) * _stickNormal[c];
            return (float)(_stickStiffness[c] * h2) * d;
        }
    }
}
