namespace Fulcrum.Scenes
{
    /// <summary>Reads one entry of <c>generators</c>: the common fields, then those of its type.</summary>
    internal static class SceneGeneratorReader
    {
        public static SceneGenerator? Read(JsonValue v, SceneDiagnostics d)
        {
            JsonObjectReader? r = JsonObjectReader.Open(v, d, "a generator object");
            if (r == null) return null;
            string? type = r.String("type", required: true);
            if (type == null) return null;
            if (!SceneNames.TryParse(type, out SceneGeneratorType kind))
            {
                d.Add(JsonPath.Member(v.Path, "type"), $"unknown generator type '{type}' (expected tower, pyramid, wall, pile, chain or dominoes)", v["type"]);
                return null;
            }
            SceneGenerator g;
            switch (kind)
            {
                case SceneGeneratorType.Tower:
                    g = new SceneTower { Count = r.Int("count", 0, required: true) };
                    break;
                case SceneGeneratorType.Pyramid:
                    g = new ScenePyramid { Count = r.Int("count", 0, required: true), Axis = ReadAxis(r, v, d) };
                    break;
                case SceneGeneratorType.Wall:
                {
                    var wall = new SceneWall { Count = r.Int("count", 0, required: true), Rows = r.Int("rows", 0, required: true), Axis = ReadAxis(r, v, d) };
                    wall.Staggered = r.Bool("staggered", wall.Staggered);
                    g = wall;
                    break;
                }
                case SceneGeneratorType.Pile:
                {
                    var pile = new ScenePile();
                    if (r.Ints("grid", 3, required: true) is int[] grid) pile.Grid = grid;
                    if (r.String("shape") is string shape)
                    {
                        if (SceneNames.TryParse(shape, out SceneShapeType s) && (s == SceneShapeType.Box || s == SceneShapeType.Sphere || s == SceneShapeType.Capsule))
                            pile.Shape = s;
                        else d.Add(JsonPath.Member(v.Path, "shape"), $"unknown pile shape '{shape}' (expected box, sphere or capsule)", v["shape"]);
                    }
                    g = pile;
                    break;
                }
                case SceneGeneratorType.Chain:
                {
                    var chain = new SceneChain { Count = r.Int("count", 0, required: true), Axis = ReadAxis(r, v, d) };
                    if (r.String("anchor") is string anchor)
                    {
                        if (SceneNames.TryParse(anchor, out SceneChainAnchor a)) chain.Anchor = a;
                        else d.Add(JsonPath.Member(v.Path, "anchor"), $"unknown anchor '{anchor}' (expected none, first or both)", v["anchor"]);
                    }
                    g = chain;
                    break;
                }
                default:
                {
                    var dominoes = new SceneDominoes { Count = r.Int("count", 0, required: true), Axis = ReadAxis(r, v, d) };
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

        static SceneAxis ReadAxis(JsonObjectReader r, JsonValue v, SceneDiagnostics d)
        {
            string? axis = r.String("axis");
            if (axis == null) return SceneAxis.X;
            if (SceneNames.TryParse(axis, out SceneAxis a)) return a;
            d.Add(JsonPath.Member(v.Path, "axis"), $"unknown axis '{axis}' (expected x or z)", v["axis"]);
            return SceneAxis.X;
        }
    }
}
