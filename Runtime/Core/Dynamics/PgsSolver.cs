namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Projected Gauss-Seidel with non-linear Gauss-Seidel position correction (the Box2D v2.x /
    /// Jolt scheme): integrate velocities, build the rows, warm start, Iterations velocity
    /// passes with no position bias (speculative contacts and limits only let gaps close),
    /// integrate positions, restitution, then PositionIterations passes that move the bodies
    /// to remove a fraction of the remaining overlap and joint error. Because the position
    /// correction never touches velocities, it adds no energy: a deep overlap is undone
    /// without the body popping out.
    /// </summary>
    internal sealed class PgsSolver : IConstraintSolver
    {
        public SolverType Type => SolverType.Pgs;

        public int SubstepCount(in WorldSettings settings) => 1;

        public float Step(SolverContext context, IslandBuilder islands, float dt)
        {
            ref readonly WorldSettings s = ref context.Settings;
            BodyStorage bodies = context.Storage;
            Integrator.IntegrateVelocities(bodies, context.BodySlot, 1, context.BodyCount - 1, s.Gravity, dt, s.MaxLinearSpeed);
            context.Prepare(islands, wide: true, keepRows: true);
            context.BuildJointTrees(s.JointTrees);
            if (s.ShockPropagation) context.PrepareShock(islands);
            context.BuildGuard(islands);
            context.Guard.Begin(context);
            context.WarmStart();
            for (int i = 0; i < s.Iterations; i++) context.Solve(useBias: false);
            // The sweep after the velocity passes, as TGS runs it after its biased ones: without
            // it the passes see a heavy body through a light one's mass, and a 1 t box pushed a
            // 1 kg box 0.8 m into the ground (the position passes, row by row too, cannot lift it back).
            if (s.ShockPropagation)
            {
                // Twice: the second sweep has no approach left to take, but each body's friction
                // on the one below it now has the load the first one put on the bodies above it
                // (TGS carries it from one substep to the next).
                context.Shock(SweepPass.Pushes);
                context.Shock(SweepPass.Friction);
            }
            context.EndGuard(islands);
            context.StoreVelocities();
            // The speed cap holds for what the constraints added too (a contradictory joint loop
            // flung bodies at 1e5 m/s in WorldFuzz).
            Integrator.ClampSpeeds(bodies, context.BodySlot, 1, context.BodyCount - 1, s.MaxLinearSpeed);
            Integrator.IntegratePositions(bodies, context.BodySlot, 1, context.BodyCount - 1, dt);
            // Restitution once the bodies have reached each other (a speculative contact closes
            // during the position update), as TGS does after its substeps.
            context.LoadVelocities();
            context.Guard.BeginAfterSolve(context);
            for (int i = 0; i < s.Iterations; i++) context.ApplyRestitution();
            context.Guard.EndAfterSolve(context);
            context.StoreVelocities();
            if (s.PositionIterations > 0)
            {
                context.LoadDeltas();
                if (s.ShockPropagation) context.HoldLightSupports();
                for (int i = 0; i < s.PositionIterations; i++) context.SolvePositions();
                context.StorePositions(turnVelocities: true);
            }
            return context.End();
        }
    }
}
