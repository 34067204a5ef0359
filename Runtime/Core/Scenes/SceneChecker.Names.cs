using System;
using System.Collections.Generic;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// Generated bodies (pyramids, towers, walls, piles, dominoes, chains) and the names
    /// every body and joint must have: unique, and every one referred to existing.
    /// Checks each generator alone; true when all are fine to expand.
    /// </summary>
    internal sealed partial class SceneChecker
    {
        bool Generators()
        {
            bool ok = true;
            long total = _doc.Bodies.Count;
            for (int k = 0; k < _doc.Generators.Count; k++)
            {
                SceneGenerator g = _doc.Generators[k];
                string path = JsonPath.Index("$.generators", k);
                int before = Errors.Count;
                if (g.Name != null && g.Name.Length == 0) Error(P(path, "name"), "must be a non-empty name (or left out)");
                Coordinate(g.At, P(path, "at"));
                Size(g.Size, P(path, "size"));
                if (NonNegative(g.Spacing, P(path, "spacing"))) Upto(g.Spacing, 0, Limits.MaxShapeSize, P(path, "spacing"), "Limits.MaxShapeSize");
                MassAndMaterial(g.Mass, g.Material, BodyType.Dynamic, path);
                switch (g)
                {
                    case SceneTower t: AtLeast(t.Count, 1, P(path, "count")); break;
                    case ScenePyramid p: AtLeast(p.Count, 1, P(path, "count")); break;
                    case SceneChain c: AtLeast(c.Count, 1, P(path, "count")); break;
                    case SceneDominoes d:
                        AtLeast(d.Count, 1, P(path, "count"));
                        if (Finite(d.TipSpeed, P(path, "tipSpeed"))) Upto(d.TipSpeed, -Limits.MaxInputSpeed, Limits.MaxInputSpeed, P(path, "tipSpeed"), "Limits.MaxInputSpeed");
                        break;
                    case SceneWall w:
                        if (AtLeast(w.Count, 1, P(path, "count")) && w.Staggered && w.Count < 2)
                            Error(P(path, "count"), "a staggered wall needs at least 2 bricks per row (or \"staggered\": false)");
                        AtLeast(w.Rows, 1, P(path, "rows"));
                        break;
                    case ScenePile pile:
                        if (pile.Grid == null || pile.Grid.Length != 3) Error(P(path, "grid"), "must be [nx, ny, nz]");
                        else
                            for (int a = 0; a < 3; a++) AtLeast(pile.Grid[a], 1, JsonPath.Index(P(path, "grid"), a));
                        if (pile.Shape != SceneShapeType.Box && pile.Shape != SceneShapeType.Sphere && pile.Shape != SceneShapeType.Capsule)
                            Error(P(path, "shape"), "must be box, sphere or capsule");
                        break;
                }
                if (Errors.Count != before) { ok = false; continue; }
                long count = g.BodyCount;
                if (count < 0 || count > SceneValidator.MaxBodies - total) { Error(path, $"the scene would have more than {SceneValidator.MaxBodies} bodies"); ok = false; }
                else total += count;
            }
            return ok;
        }

        // The set of all body names, reporting duplicates (generated names included when the generators are fine).
        HashSet<string> BodyNames(bool withGenerated)
        {
            var first = new Dictionary<string, string>();
            for (int i = 0; i < _doc.Bodies.Count; i++)
            {
                string? name = _doc.Bodies[i]?.Name;
                if (string.IsNullOrEmpty(name)) continue;
                string path = JsonPath.Index("$.bodies", i);
                if (first.TryGetValue(name!, out string? at)) Error(P(path, "name"), $"duplicate body name '{name}' (first used at {at})");
                else first.Add(name!, path);
            }
            if (withGenerated)
            {
                var bodies = new List<SceneBody>();
                var joints = new List<SceneJoint>();
                for (int k = 0; k < _doc.Generators.Count; k++)
                {
                    string path = JsonPath.Index("$.generators", k);
                    bodies.Clear();
                    _doc.Generators[k].Expand(bodies, joints);
                    foreach (SceneBody b in bodies)
                    {
                        if (first.TryGetValue(b.Name, out string? at))
                        {
                            Error(path, $"generated body name '{b.Name}' is already used at {at}: give the generator a \"name\"");
                            break;
                        }
                        first.Add(b.Name, path);
                    }
                }
            }
            return new HashSet<string>(first.Keys);
        }

        void JointNames()
        {
            SceneExpansion e = _doc.Expand();
            var first = new Dictionary<string, string>();
            for (int i = 0; i < e.Joints.Count; i++)
            {
                string? name = e.Joints[i]?.Name;
                if (name == null) continue;
                string source = e.JointSources[i];
                bool generated = i >= _doc.Joints.Count;
                if (first.TryGetValue(name, out string? at))
                    Error(generated ? source : P(source, "name"), $"duplicate joint name '{name}' (first used at {at})");
                else first.Add(name, source);
            }
        }

        // When a generator was rejected its bodies were never made: a name that would be one
        // of them gets the benefit of the doubt rather than a second, misleading error.
        bool Exists(string name, HashSet<string> bodies)
        {
            if (bodies.Contains(name)) return true;
            if (_generatorsExpanded) return false;
            foreach (SceneGenerator g in _doc.Generators)
                if (name.StartsWith(g.Prefix + "/", StringComparison.Ordinal)) return true;
            return false;
        }
    }
}
