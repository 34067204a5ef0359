namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Temporal Gauss-Seidel with soft constraints and relaxation (Catto's "soft step", Box2D
    /// v3; PhysX's TGS is the same idea with a rigid bias). The step is cut into Substeps;
    /// per substep: integrate velocities, warm start, Iterations biased passes (soft rows pull
    /// positions back at a bounded rate), integrate positions, RelaxIterations unbiased passes
    /// that remove the velocity the bias added, then restitution for the impacts of the
    /// substep (Iterations passes, only in steps with a bouncy contact).
    /// Contact separations and joint errors are re-evaluated each substep from the bodies'
    /// motion, so small substeps act like small steps at the price of one narrow phase.
    /// </summary>
    internal sealed class TgsSolver : IConstraintSolver
    {
        public SolverType Type => SolverType.Tgs;

        public int SubstepCount(in WorldSettings settings) => settings.Substeps;

        public float Step(SolverContext context, IslandBuilder islands, float dt)
        {
            ref readonly WorldSettings s = ref context.Settings;
            context.Prepare(islands, wide: true);
            context.BuildJointTrees(s.JointTrees);
            if (s.ShockPropagation) context.PrepareShock(islands);
            context.BuildGuard(islands);
            for (int sub = 0; sub < s.Substeps; sub++)
            {
                context.IntegrateVelocities();
                if (context.HasRestitution) context.RefreshApproach();
                context.Guard.Begin(context);
                context.WarmStart();
                for (int i = 0; i < s.Iterations; i++) context.Solve(useBias: true, trees: i == s.Iterations - 1);
                if (s.ShockPropagation) context.Shock();
                context.IntegratePositions();
                context.Guard.BeginAfterSolve(context);
                for (int i = 0; i < s.RelaxIterations; i++) context.Solve(useBias: false);
                // Restitution for the impacts of this substep. The points of a face contact
                // share one body: the bounce needs the same number of Gauss-Seidel passes as any
                // other row to reach -e v0 at every point.
                if (context.HasRestitution)
                    for (int i = 0; i < s.Iterations; i++) context.ApplyRestitution();
                context.Guard.EndAfterSolve(context);
                // The guard's window closes after restitution too: a bounce (e <= 1) gives back
                // at most the energy of the approach, but its targets come from the substep's
                // start, and in a jointed island a compound spun from 114 to 483 rad/s in one
                // restitution pass (WorldFuzz seed 1547).
                context.EndGuard(islands);
                context.AccumulateApplied();
            }
            context.StoreBodies();
            return context.End();
        }
    }
}
