namespace Fulcrum.SoftBodies
{
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
