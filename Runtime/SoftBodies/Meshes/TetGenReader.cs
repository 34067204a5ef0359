using System;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Reads TetGen's .node and .ele text (https://wias-berlin.de/software/tetgen/fformats.html):
    /// .node: "count 3 attributes markers" then "index x y z [attributes] [marker]";
    /// .ele: "count 4|10 regionFlag" then "index n0 n1 n2 n3 [...]" (10-node tets keep their corners).
    /// Indices may start at 0 or 1 (the first node's index decides). If most tets are
    /// negatively oriented in our convention (det[x1-x0, x2-x0, x3-x0] &gt; 0), the file uses the
    /// other one and every tet is flipped; tets still inverted after that are an error, left to
    /// <see cref="SoftMesh"/> validation, which names the element.
    /// </summary>
    internal static class TetGenReader
    {
        public static void Read(string nodeText, string eleText, out Vector3[] vertices, out int[] tets)
        {
            if (nodeText == null) throw new ArgumentNullException(nameof(nodeText));
            if (eleText == null) throw new ArgumentNullException(nameof(eleText));
            var nodes = TextTokens.Lines(nodeText);
            if (nodes.Count == 0) throw new ArgumentException("tetgen .node text is empty.", nameof(nodeText));
            int count = TextTokens.Int(nodes[0].Tokens[0], "tetgen .node", nodes[0].Line);
            if (nodes[0].Tokens.Length > 1 && TextTokens.Int(nodes[0].Tokens[1], "tetgen .node", nodes[0].Line) != 3)
                throw new ArgumentException($"tetgen .node line {nodes[0].Line}: only 3-dimensional nodes are supported.", nameof(nodeText));
            if (count <= 0 || nodes.Count - 1 < count)
                throw new ArgumentException($"tetgen .node declares {count} nodes but has {nodes.Count - 1} node lines.", nameof(nodeText));
            vertices = new Vector3[count];
            int firstIndex = 0;
            for (int i = 0; i < count; i++)
            {
                var (line, tok) = nodes[i + 1];
                if (tok.Length < 4) throw new ArgumentException($"tetgen .node line {line}: expected 'index x y z'.", nameof(nodeText));
                int index = TextTokens.Int(tok[0], "tetgen .node", line);
                if (i == 0) firstIndex = index;
                if (index - firstIndex != i) throw new ArgumentException($"tetgen .node line {line}: node index {index} is out of sequence.", nameof(nodeText));
                vertices[i] = new Vector3(TextTokens.Float(tok[1], "tetgen .node", line), TextTokens.Float(tok[2], "tetgen .node", line), TextTokens.Float(tok[3], "tetgen .node", line));
            }

            var eles = TextTokens.Lines(eleText);
            if (eles.Count == 0) throw new ArgumentException("tetgen .ele text is empty.", nameof(eleText));
            int tetCount = TextTokens.Int(eles[0].Tokens[0], "tetgen .ele", eles[0].Line);
            int perTet = eles[0].Tokens.Length > 1 ? TextTokens.Int(eles[0].Tokens[1], "tetgen .ele", eles[0].Line) : 4;
            if (perTet != 4 && perTet != 10) throw new ArgumentException($"tetgen .ele line {eles[0].Line}: tets must have 4 or 10 nodes, got {perTet}.", nameof(eleText));
            if (tetCount <= 0 || eles.Count - 1 < tetCount)
                throw new ArgumentException($"tetgen .ele declares {tetCount} tets but has {eles.Count - 1} tet lines.", nameof(eleText));
            tets = new int[4 * tetCount];
            for (int t = 0; t < tetCount; t++)
            {
                var (line, tok) = eles[t + 1];
                if (tok.Length < 1 + perTet) throw new ArgumentException($"tetgen .ele line {line}: expected an index and {perTet} nodes.", nameof(eleText));
                for (int q = 0; q < 4; q++)
                {
                    int v = TextTokens.Int(tok[1 + q], "tetgen .ele", line) - firstIndex;
                    if ((uint)v >= (uint)count) throw new ArgumentException($"tetgen .ele line {line}: node {v + firstIndex} does not exist.", nameof(eleText));
                    tets[4 * t + q] = v;
                }
            }

            int negative = 0;
            for (int t = 0; t < tets.Length; t += 4)
                if (GridTetGenerator.SignedVolume(vertices, tets, t) < 0) negative++;
            if (2 * negative > tetCount)
                for (int t = 0; t < tets.Length; t += 4) (tets[t + 2], tets[t + 3]) = (tets[t + 3], tets[t + 2]);
        }
    }
}
