namespace Fulcrum.SoftBodies
{
    /// <summary>One colour range of membrane triangles: the position solve, or with <see cref="ElementRangeJob.Damping"/> the velocity damping pass.</summary>
    internal sealed class MembraneRangeJob : ElementRangeJob
    {
        public MembraneRangeJob(SoftBody body) : base(body) { }

        public override void Execute(int start, int end)
        {
            SoftBody b = Body;
            if (Damping) RayleighDamping.Membranes(b.MembraneModel, b.Thickness, b.Tris, b.X, b.V, b.W, start, end, H, DampingTime);
            else XpbdMembraneSolver.Solve(b.MembraneModel, b.Thickness, b.Tris, b.TriLambda, b.X, b.XPrev, b.W, b.M, b.FreeW, start, end, H);
        }
    }
}
