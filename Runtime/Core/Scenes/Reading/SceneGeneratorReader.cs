namespace Fulcrum.Scenes
{
    /// <summary>Reads one entry of <c>generators</c>: the common fields, then those of its type.</summary>
    internal static class SceneGeneratorReader
    {
        public static SceneGenerator? Read(JsonValue v, SceneDiagnostics d)
        {
            JsonObjectReader? r = JsonObjectReader.OpenTyped(v, d, "a generator object", SceneNames.GeneratorTypes, "generator type", out SceneGeneratorType kind);
            if (r == null) return null;
            SceneGenerator g;
            switch (kind)
            {
                case SceneGeneratorType.Tower:
                    g = new SceneTower { Count = r.Int("count", 0, required: true) };
                    break;
                case SceneGeneratorType.Pyramid:
                    g = new ScenePyramid { Count = r.Int("count", 0, required: true), Axis = ReadAxis(r) };
                    break;
                case SceneGeneratorType.Wall:
                {
                    var wall = new SceneWall { Count = r.Int("count", 0, required: true), Rows = r.Int("rows", 0, required: true), Axis = ReadAxis(r) };
                    wall.Staggered = r.Bool("staggered", wall.Staggered);
                    g = wall;
                    break;
                }
                case SceneGeneratorType.Pile:
                {
                    var pile = new ScenePile();
                    if (r.Ints("grid", 3, required: true) is int[] grid) pile.Grid = grid;
                    if (r.Name("shape", SceneNames.PileShapes, "pile shape", out SceneShapeType shape)) pile.Shape = shape;
                    g = pile;
                    break;
                }
                case SceneGeneratorType.Chain:
                {
                    var chain = new SceneChain { Count = r.Int("count", 0, required: true), Axis = ReadAxis(r) };
                    if (r.Name("anchor", SceneNames.ChainAnchors, "anchor", out SceneChainAnchor anchor)) chain.Anchor = anchor;
                    g = chain;
                    break;
                }
                default:
                {
                    var dominoes = new SceneDominoes { Count = r.Int("count", 0, required: true), Axis = ReadAxis(r) };
                    dominoes.TipSpeed = r.Float("tipSpeed", dominoes.TipSpeed);
                    g = dominoes;
                    break;
                }
            }
            g.Name = r.String("name");
            g.At = r.Vector("at", g.At);
            g.Size = r.Vector("size", g.Size);
            g.Spacing = r.Float("spacing", g.Spacing);
            g.Mass = r.OptionalFloat("mass");
            g.Material = r.String("material");
            r.Finish();
            return g;
        }

        static SceneAxis ReadAxis(JsonObjectReader r) =>
            r.Name("axis", SceneNames.Axes, "axis", out SceneAxis a) ? a : SceneAxis.X;
    }
}
