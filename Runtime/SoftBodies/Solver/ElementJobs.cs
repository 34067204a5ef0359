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

    /// <summary>One colour range of membrane triangles.</summary>
    internal sealed class MembraneRangeJob : RangeJob
    {
        readonly SoftBody _body;
        public float H, Gamma;

        public MembraneRangeJob(SoftBody body) => _body = body;

        public override void Execute(int start, int end) =>
            XpbdMembraneSolver.Solve(_body.MembraneModel, _body.Thickness, _body.Tris, _body.TriLambda, _body.X, _body.XPrev, _body.W, start, end, H, Gamma);
    }

    /// <summary>One colour range of bending hinges.</summary>
    internal sealed class BendingRangeJob : RangeJob
    {
        readonly SoftBody _body;
        public float H, Gamma;

        public BendingRangeJob(SoftBody body) => _body = body;

        public override void Execute(int start, int end) =>
            XpbdBendingSolver.Solve(_body.Bends, _body.BendLambda, _body.X, _body.XPrev, _body.W, start, end, H, Gamma);
    }
}
