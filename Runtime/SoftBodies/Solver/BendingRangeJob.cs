namespace Fulcrum.SoftBodies
{
    /// <summary>One colour range of bending hinges: the position solve, or with <see cref="ElementRangeJob.Damping"/> the velocity damping pass.</summary>
    internal sealed class BendingRangeJob : ElementRangeJob
    {
        public BendingRangeJob(SoftBody body) : base(body) { }

        public override void Execute(int start, int end)
        {
            SoftBody b = Body;
            if (Damping) RayleighDamping.Bends(b.Bends, b.X, b.V, b.W, start, end, H, DampingTime);
            else XpbdBendingSolver.Solve(b.Bends, b.BendLambda, b.X, b.XPrev, b.W, b.M, b.FreeW, start, end, H);
        }
    }
}
