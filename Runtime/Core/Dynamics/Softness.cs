using System;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Coefficients of a soft constraint: a spring of natural frequency f (Hz) and damping
    /// ratio zeta, integrated implicitly over the (sub)step h. With omega = 2 pi f the
    /// implicit-Euler spring-damper gives (Catto, "Soft Step", Solver2D 2024; Box2D v3):
    /// <code>
    ///   biasRate     = omega / (2 zeta + h omega)
    ///   massScale    = h omega (2 zeta + h omega) / (1 + h omega (2 zeta + h omega))
    ///   impulseScale = 1 / (1 + h omega (2 zeta + h omega))
    /// </code>
    /// and the row update is dLambda = -m_eff massScale (Jv + biasRate C) - impulseScale lambda.
    /// massScale + impulseScale = 1; as f grows the row tends to a rigid one that removes the
    /// whole error in one (sub)step. f = 0 gives a rigid row with no position feedback.
    /// </summary>
    internal readonly struct Softness
    {
        /// <summary>Velocity bias per metre (or radian) of error, 1/s.</summary>
        public readonly float BiasRate;
        /// <summary>Scale on the effective mass, in (0, 1].</summary>
        public readonly float MassScale;
        /// <summary>Fraction of the accumulated impulse that leaks each iteration, in [0, 1).</summary>
        public readonly float ImpulseScale;

        /// <summary>
        /// The largest bias velocity the row asks for, m/s or rad/s (joints: a wildly violated
        /// joint is pulled together at this speed at most, not at biasRate times its error).
        /// </summary>
        public readonly float MaxBias;

        public Softness(float biasRate, float massScale, float impulseScale)
            : this(biasRate, massScale, impulseScale, float.PositiveInfinity)
        {
        }

        Softness(float biasRate, float massScale, float impulseScale, float maxBias)
        {
            BiasRate = biasRate;
            MassScale = massScale;
            ImpulseScale = impulseScale;
            MaxBias = maxBias;
        }

        /// <summary>This softness with its bias velocity capped at <paramref name="maxBias"/>.</summary>
        public Softness WithMaxBias(float maxBias) => new Softness(BiasRate, MassScale, ImpulseScale, maxBias);

        /// <summary>
        /// The row's coefficients for a bias of length <paramref name="biasLength"/> (biasRate
        /// |C|). Below <see cref="MaxBias"/> they are this softness's own. Above it the bias is
        /// scaled down by <paramref name="biasScale"/> = MaxBias / biasLength, and the spring is
        /// stiffened by the same ratio r: massScale / impulseScale, which sets the force the row
        /// holds at rest (lambda = m_eff (massScale / impulseScale) bias), is multiplied by r.
        /// The row then still holds the force of the uncapped spring, k C, while pulling at
        /// MaxBias at most (up to r = <see cref="MaxStiffening"/>; beyond, the force grows no
        /// more). Capping the bias alone capped the force too: a 1000 kg load on a chain of 1 kg
        /// links sank to the floor. Continuous at r = 1.
        /// </summary>
        public void Capped(float biasLength, out float biasScale, out float massScale, out float impulseScale)
        {
            if (!(biasLength > MaxBias) || ImpulseScale == 0)
            {
                biasScale = biasLength > MaxBias ? MaxBias / biasLength : 1f;
                massScale = MassScale;
                impulseScale = ImpulseScale;
                return;
            }
            float r = biasLength / MaxBias;
            float q = MassScale / ImpulseScale * MathF.Min(r, MaxStiffening);
            biasScale = 1f / r;
            impulseScale = 1f / (1f + q);
            massScale = q * impulseScale;
        }

        /// <summary>The bias velocity for the error <paramref name="c"/> and the row's scales (see <see cref="Capped"/>).</summary>
        public float Bias(float c, out float massScale, out float impulseScale)
        {
            float bias = BiasRate * c;
            Capped(MathF.Abs(bias), out float k, out massScale, out impulseScale);
            return bias * k;
        }

        /// <summary>The bias velocity for the error vector <paramref name="c"/> and the row's scales; the cap keeps the bias's direction.</summary>
        public System.Numerics.Vector3 Bias(System.Numerics.Vector3 c, out float massScale, out float impulseScale)
        {
            System.Numerics.Vector3 bias = BiasRate * c;
            Capped(bias.Length(), out float k, out massScale, out impulseScale);
            return bias * k;
        }

        /// <summary>
        /// The impulse update of a three-row block (a point or a rotation lock) with effective
        /// mass <paramref name="effectiveMass"/>, velocity error <paramref name="jv"/>, position
        /// error <paramref name="c"/> and accumulated impulse <paramref name="accumulated"/>: this
        /// soft step's update with <paramref name="useBias"/>, the rigid one without bias otherwise.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        public System.Numerics.Vector3 BlockImpulse(in Mathematics.Mat3 effectiveMass, System.Numerics.Vector3 jv, System.Numerics.Vector3 c,
            System.Numerics.Vector3 accumulated, bool useBias)
        {
            if (!useBias) return -(effectiveMass * jv);
            System.Numerics.Vector3 bias = Bias(c, out float massScale, out float impulseScale);
            return -massScale * (effectiveMass * (jv + bias)) - impulseScale * accumulated;
        }

        /// <summary>
        /// The most <see cref="Capped"/> stiffens a row: a joint pulled apart by a load holds up
        /// to this many times the force of its spring at the cap (a 10 t load under one 1 kg
        /// link: 1.36 m, against 1.34 m unlimited; at 4 it fell 13 m, at 2, 39 m). Beyond it
        /// lies a joint created metres from its target, for which the cap exists: stiffened
        /// without bound (21 times in WorldFuzz seed 69) the rows of joints that cannot all be
        /// met turned nearly rigid and, with no relax pass, lifted a 1.6 t body 12 m.
        /// </summary>
        const float MaxStiffening = 8f;

        /// <summary>A rigid row without position feedback.</summary>
        public static Softness Rigid => new Softness(0, 1, 0);

        /// <summary>The coefficients for <paramref name="hertz"/> and <paramref name="dampingRatio"/> over the step <paramref name="h"/>.</summary>
        public static Softness Make(float hertz, float dampingRatio, float h)
        {
            if (!(hertz > 0)) return Rigid;
            float omega = 2f * MathF.PI * hertz;
            float a1 = 2f * dampingRatio + h * omega;
            float a2 = h * omega * a1;
            float a3 = 1f / (1f + a2);
            return new Softness(omega / a1, a2 * a3, a3);
        }

        /// <summary>
        /// The stiffest spring that an explicit-in-time velocity solver keeps stable over a
        /// step h: a quarter of the step rate (Box2D v3's contact hertz clamp).
        /// </summary>
        public static float MaxStableHertz(float h) => 0.25f / h;
    }
}
