namespace Fulcrum.SoftBodies
{
    /// <summary>One colour range of tets for <see cref="ParallelRanges"/>; the model is a type argument so the loop is specialised.</summary>
    internal sealed class TetRangeJob<TModel> : RangeJob where TModel : struct, IHyperelasticModel
    {
        readonly SoftBody _body;
        readonly TModel _model;
        public float H, Gamma;

        public TetRangeJob(SoftBody body, in TModel model)
        {
            _body = body;
            _model = model;
        }

        public override void Execute(int start, int end) =>
            XpbdTetSolver.Solve(_model, _body.Tets, _body.TetLambda, _body.X, _body.XPrev, _body.W, start, end, H, Gamma);
    }
}
