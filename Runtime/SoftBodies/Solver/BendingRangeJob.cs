namespace Fulcrum.SoftBodies
{
    /// <summary>One colour range of bending hinges.</summary>
    internal sealed class BendingRangeJob : RangeJob
    {
        readonly SoftBody _body;
        public float H, DampingTime;
        public bool Damping;

        public BendingRangeJob(SoftBody body) => _body = body;

        public override void Execute(int start, int end)
        {
            if (Damping) RayleighDamping.Bends(_body.Bends, _body.X, _body.V, _body.W, start, end, H, DampingTime);
            else XpbdBendingSolver.Solve(_body.Bends, _body.BendLambda, _body.X, _body.XPrev, _body.W, _body.M, _body.FreeW, start, end, H);
        }
    }
}
