using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// An energy density written, after Macklin and Mueller 2021 ("A Constraint-based
    /// Formulation of Stable Neo-Hookean Materials"), as two XPBD constraints:
    /// Psi(F) = mu/2 C_D(F)^2 + lambda/2 C_H(F)^2 + const, so that a tet of rest volume V has
    /// compliances 1/(mu V) and 1/(lambda V). The solver is generic over this interface so
    /// that each model's loop is compiled on its own (no virtual call per element).
    /// </summary>
    internal interface IHyperelasticModel
    {
        /// <summary>The weight of C_D: mu of the energy, Pa.</summary>
        float DeviatoricStiffness { get; }

        /// <summary>The weight of C_H: lambda of the energy, Pa.</summary>
        float HydrostaticStiffness { get; }

        /// <summary>Evaluates both constraints and their derivatives with respect to F.</summary>
        void Constraints(in Mat3 f, out float cDev, out Mat3 dDev, out float cVol, out Mat3 dVol);

        /// <summary>Psi(F), J/m^3, zero at F = I.</summary>
        float EnergyDensity(in Mat3 f);
    }
}
