using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Finds, for each probe (a rest-space point), the rest element it lies in and its
    /// barycentric coordinates there. A point just outside the mesh (a carved surface, a probe
    /// on a face) takes the nearest element; one clearly outside is an error.
    /// </summary>
    internal static class ProbeBinder
    {
        public static ProbeBinding[] Bind(SoftMesh mesh, Vector3[]? probes)
        {
            if (probes == null || probes.Length == 0) return Array.Empty<ProbeBinding>();
            var result = new ProbeBinding[probes.Length];
            for (int p = 0; p < probes.Length; p++)
                result[p] = mesh.IsShell ? BindTriangle(mesh, probes[p], p) : BindTet(mesh, probes[p], p);
            return result;
        }

        static ProbeBinding BindTet(SoftMesh mesh, Vector3 point, int index)
        {
            Vector3[] v = mesh.VertexArray;
            int[] tets = mesh.TetArray;
            float best = float.NegativeInfinity;
            ProbeBinding binding = default;
            for (int t = 0; t < tets.Length; t += 4)
            {
                Vector3 x0 = v[tets[t]];
                Mat3 inv = new Mat3(v[tets[t + 1]] - x0, v[tets[t + 2]] - x0, v[tets[t + 3]] - x0).Inverse();
                Vector3 b = inv * (point - x0);
                float b0 = 1f - b.X - b.Y - b.Z;
                float worst = MathF.Min(MathF.Min(b0, b.X), MathF.Min(b.Y, b.Z));
                if (worst <= best) continue;
                best = worst;
                binding = new ProbeBinding { A = tets[t], B = tets[t + 1], C = tets[t + 2], D = tets[t + 3], Weights = new Vector4(b0, b.X, b.Y, b.Z) };
            }
            // Barycentric -0.5 is half a tet outside its face: beyond that the point is not in the body.
            if (best < -0.5f)
                throw new ArgumentException($"softBody.Probes[{index}] = {point} lies outside the mesh.", $"softBody.Probes[{index}]");
            return binding;
        }

        static ProbeBinding BindTriangle(SoftMesh mesh, Vector3 point, int index)
        {
            Vector3[] v = mesh.VertexArray;
            int[] tris = mesh.TriangleArray;
            float best = float.PositiveInfinity;
            ProbeBinding binding = default;
            for (int t = 0; t < tris.Length; t += 3)
            {
                Vector3 a = v[tris[t]], b = v[tris[t + 1]], c = v[tris[t + 2]];
                Vector3 w = ClosestBarycentric(a, b, c, point);
                Vector3 q = w.X * a + w.Y * b + w.Z * c;
                float d = (q - point).LengthSquared();
                if (d >= best) continue;
                best = d;
                binding = new ProbeBinding { A = tris[t], B = tris[t + 1], C = tris[t + 2], D = -1, Weights = new Vector4(w, 0f) };
            }
            float size = mesh.Bounds.Size.Length();
            if (MathF.Sqrt(best) > 0.05f * size + 1e-6f)
                throw new ArgumentException($"softBody.Probes[{index}] = {point} is not on the shell.", $"softBody.Probes[{index}]");
            return binding;
        }

        // Barycentric coordinates of the point of triangle abc closest to p (projection, then clamped to an edge if outside).
        static Vector3 ClosestBarycentric(Vector3 a, Vector3 b, Vector3 c, Vector3 p)
        {
            Vector3 e1 = b - a, e2 = c - a, d = p - a;
            float d11 = Vector3.Dot(e1, e1), d12 = Vector3.Dot(e1, e2), d22 = Vector3.Dot(e2, e2);
            float p1 = Vector3.Dot(d, e1), p2 = Vector3.Dot(d, e2);
            float det = d11 * d22 - d12 * d12;
            float u = (d22 * p1 - d12 * p2) / det, w = (d11 * p2 - d12 * p1) / det;
            if (u >= 0 && w >= 0 && u + w <= 1) return new Vector3(1 - u - w, u, w);
            Vector3 best = default;
            float bestD = float.PositiveInfinity;
            Edge(a, b, p, new Vector3(1, 0, 0), new Vector3(0, 1, 0), ref best, ref bestD);
            Edge(b, c, p, new Vector3(0, 1, 0), new Vector3(0, 0, 1), ref best, ref bestD);
            Edge(c, a, p, new Vector3(0, 0, 1), new Vector3(1, 0, 0), ref best, ref bestD);
            return best;
        }

        static void Edge(Vector3 a, Vector3 b, Vector3 p, Vector3 wa, Vector3 wb, ref Vector3 best, ref float bestD)
        {
            Vector3 e = b - a;
            float s = Math.Clamp(Vector3.Dot(p - a, e) / e.LengthSquared(), 0f, 1f);
            float d = (a + s * e - p).LengthSquared();
            if (d < bestD)
            {
                bestD = d;
                best = (1 - s) * wa + s * wb;
            }
        }
    }
}
