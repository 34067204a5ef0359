namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// One colour range of tets for the <see cref="IParallelScheduler"/>: the position solve, or with
    /// <see cref="ElementRangeJob.Damping"/> the velocity damping pass. The model is a type argument so the loop is specialised.
    /// </summary>
    internal sealed class TetRangeJob<TModel> : ElementRangeJob where TModel : struct, IHyperelasticModel
    {
        readonly TModel _model;

        public TetRangeJob(SoftBody body, in TModel model) : base(body) => _model = model;

        public override void Execute(int start, int end)
        {
            SoftBody b = Body;
            if (Damping)
            {
#if NET
                if (TetStream.WideKernels) start = RayleighDampingWide.Tets(_model.DeviatoricStiffness, _model.HydrostaticStiffness, b.TetData, b.X, b.V, start, end, H, DampingTime);
#endif
                RayleighDamping.Tets(_model.DeviatoricStiffness, _model.HydrostaticStiffness, b.TetData, b.X, b.V, b.W, b.M, b.FreeW, start, end, H, DampingTime);
            }
            else
            {
#if NET
                if (TetStream.WideKernels && _model is StableNeoHookeanEnergy stable)
                    start = XpbdTetSolverWide.Solve(stable, b.TetData, b.TetLambda, DampingTime > 0f, b.X, b.XPrev, start, end, H);
#endif
                XpbdTetSolver.Solve(_model, b.TetData, b.TetLambda, DampingTime > 0f, b.X, b.XPrev, b.W, b.M, b.FreeW, start, end, H);
            }
        }
    }
}
