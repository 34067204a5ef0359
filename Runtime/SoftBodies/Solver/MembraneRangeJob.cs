namespace Fulcrum.SoftBodies
{
    /// <summary>One colour range of membrane triangles: the position solve, or with <see cref="Damping"/> the velocity damping pass.</summary>
    internal sealed class MembraneRangeJob : RangeJob
    {
        readonly SoftBody _body;
        public float H, DampingTime;
        public bool Damping;

        public MembraneRangeJob(SoftBody body) => _body = body;

        public override void Execute(int start, int end)
        {
            if (Damping) RayleighDamping.Membranes(_body.MembraneModel, _body.Thickness, _body.Tris, _body.X, _body.V, _body.W, start, end, H, DampingTime);
            else XpbdMembraneSolver.Solve(_body.MembraneModel, _body.Thickness, _body.Tris, _body.TriLambda, _body.X, _body.XPrev, _body.W, _body.M, _body.FreeW, start, end, H);
        }
    }
}
