using System;
using System.Collections.Generic;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Reads the surface of a Wavefront OBJ text: <c>v x y z</c> and <c>f a b c ...</c> lines
    /// (indices 1-based, negative ones relative to the end, <c>a/t/n</c> forms accepted);
    /// polygons are split into fans. Every other statement is ignored. Vertices that no face
    /// uses are dropped.
    /// </summary>
    internal static class ObjReader
    {
        public static void Read(string text, out Vector3[] vertices, out int[] triangles)
        {
            if (text == null) throw new ArgumentNullException(nameof(text));
            var positions = new List<Vector3>();
            var faces = new List<int>();
            var polygon = new List<int>();
            foreach (var (line, tok) in TextTokens.Lines(text))
            {
                if (tok[0] == "v")
                {
                    if (tok.Length < 4) throw new ArgumentException($"obj line {line}: expected 'v x y z'.", "obj");
                    positions.Add(new Vector3(TextTokens.Float(tok[1], "obj", line), TextTokens.Float(tok[2], "obj", line), TextTokens.Float(tok[3], "obj", line)));
                }
                else if (tok[0] == "f")
                {
                    if (tok.Length < 4) throw new ArgumentException($"obj line {line}: a face needs at least 3 vertices.", "obj");
                    polygon.Clear();
                    for (int k = 1; k < tok.Length; k++)
                    {
                        string s = tok[k];
                        int slash = s.IndexOf('/');
                        int index = TextTokens.Int(slash >= 0 ? s.Substring(0, slash) : s, "obj", line);
                        int v = index > 0 ? index - 1 : positions.Count + index;
                        if (index == 0 || (uint)v >= (uint)positions.Count)
                            throw new ArgumentException($"obj line {line}: vertex {index} does not exist.", "obj");
                        polygon.Add(v);
                    }
                    for (int k = 1; k + 1 < polygon.Count; k++)
                    {
                        faces.Add(polygon[0]);
                        faces.Add(polygon[k]);
                        faces.Add(polygon[k + 1]);
                    }
                }
            }
            if (faces.Count == 0) throw new ArgumentException("obj text has no faces.", "obj");
            MeshCompaction.DropUnused(positions, faces, out vertices, out triangles);
        }
    }
}
