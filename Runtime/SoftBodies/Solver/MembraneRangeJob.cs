namespace Fulcrum.SoftBodies
{
    /// <summary>One colour range of membrane triangles.</summary>
    internal sealed class MembraneRangeJob : RangeJob
    {
        readonly SoftBody _body;
        public float H, Gamma;

        public MembraneRangeJob(SoftBody body) => _body = body;

        public override void Execute(int start, int end) =>
            XpbdMembraneSolver.Solve(_body.MembraneModel, _body.Thickness, _body.Tris, _body.TriLambda, _body.X, _body.XPrev, _body.W, start, end, H, Gamma);
    }
}
