namespace Fulcrum.Dynamics
{
    /// <summary>
    /// A constraint solver: advances the bodies that take part in constraints by one step.
    /// The world picks one per step from <see cref="WorldSettings.Solver"/>; both compose the
    /// same passes of <see cref="SolverContext"/>.
    /// </summary>
    internal interface IConstraintSolver
    {
        /// <summary>Which solver this is.</summary>
        SolverType Type { get; }

        /// <summary>Substeps the solver takes per step with these settings.</summary>
        int SubstepCount(in WorldSettings settings);

        /// <summary>
        /// Integrates, solves and moves the constrained bodies over <paramref name="dt"/>;
        /// <see cref="SolverContext.Begin"/> has run. Returns the largest joint error, m.
        /// </summary>
        float Step(SolverContext context, IslandBuilder islands, float dt);
    }
}
