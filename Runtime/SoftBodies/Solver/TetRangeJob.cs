namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// One colour range of tets for the <see cref="IParallelScheduler"/>: the position solve, or with
    /// <see cref="Damping"/> the velocity damping pass. The model is a type argument so the loop is specialised.
    /// </summary>
    internal sealed class TetRangeJob<TModel> : RangeJob where TModel : struct, IHyperelasticModel
    {
        readonly SoftBody _body;
        readonly TModel _model;
        public float H, DampingTime;
        public bool Damping;

        public TetRangeJob(SoftBody body, in TModel model)
        {
            _body = body;
            _model = model;
        }

        public override void Execute(int start, int end)
        {
            if (Damping) RayleighDamping.Tets(_model.DeviatoricStiffness, _model.HydrostaticStiffness, _body.Tets, _body.TetGrad, _body.X, _body.V, _body.W, _body.M, _body.FreeW, start, end, H, DampingTime);
            else XpbdTetSolver.Solve(_model, _body.Tets, _body.TetLambda, DampingTime > 0f ? _body.TetGrad : null, _body.X, _body.XPrev, _body.W, _body.M, _body.FreeW, start, end, H);
        }
    }
}
