using System;
using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// The GJK simplex (1 to 4 vertices of the Minkowski difference A - B) and its reduction to
    /// the smallest sub-simplex holding the point closest to the origin, by the Voronoi-region
    /// tests of Ericson, Real-Time Collision Detection, 5.1.2 (segment), 5.1.5 (triangle) and
    /// 5.1.6 (tetrahedron). Weights are the barycentric coordinates of that point.
    /// </summary>
    internal struct Simplex
    {
        public SimplexVertex V0, V1, V2, V3;
        public int Count;

        /// <summary>A copy of vertex <paramref name="i"/>.</summary>
        public readonly SimplexVertex Get(int i) => i == 0 ? V0 : i == 1 ? V1 : i == 2 ? V2 : V3;

        /// <summary>The weighted point closest to the origin.</summary>
        public readonly Vector3 ClosestPoint()
        {
            Vector3 v = V0.W * V0.Weight;
            if (Count > 1) v += V1.W * V1.Weight;
            if (Count > 2) v += V2.W * V2.Weight;
            if (Count > 3) v += V3.W * V3.Weight;
            return v;
        }

        /// <summary>The closest points on cores A and B.</summary>
        public readonly void WitnessPoints(out Vector3 a, out Vector3 b)
        {
            a = V0.A * V0.Weight;
            b = V0.B * V0.Weight;
            if (Count > 1) { a += V1.A * V1.Weight; b += V1.B * V1.Weight; }
            if (Count > 2) { a += V2.A * V2.Weight; b += V2.B * V2.Weight; }
            if (Count > 3) { a += V3.A * V3.Weight; b += V3.B * V3.Weight; }
        }

        /// <summary>True when a vertex with the same pair of indices is already present.</summary>
        public readonly bool Contains(int indexA, int indexB)
        {
            if (V0.IndexA == indexA && V0.IndexB == indexB) return true;
            if (Count > 1 && V1.IndexA == indexA && V1.IndexB == indexB) return true;
            if (Count > 2 && V2.IndexA == indexA && V2.IndexB == indexB) return true;
            return Count > 3 && V3.IndexA == indexA && V3.IndexB == indexB;
        }

        /// <summary>
        /// Reduces to the sub-simplex nearest the origin and sets the weights; returns false
        /// when the origin lies inside the tetrahedron (the cores overlap).
        /// </summary>
        public bool Solve()
        {
            switch (Count)
            {
                case 1: V0.Weight = 1; return true;
                case 2: SolveSegment(); return true;
                case 3: SolveTriangle(); return true;
                default: return SolveTetrahedron();
            }
        }

        void SolveSegment()
        {
            Vector3 e = V1.W - V0.W;
            float t = -Vector3.Dot(V0.W, e);
            float ee = e.LengthSquared();
            if (t <= 0 || ee <= 0) { Keep1(0); return; }
            if (t >= ee) { Keep1(1); return; }
            t /= ee;
            V0.Weight = 1 - t;
            V1.Weight = t;
            Count = 2;
        }

        void SolveTriangle()
        {
            Vector3 a = V0.W, b = V1.W, c = V2.W;
            Vector3 ab = b - a, ac = c - a;
            float d1 = -Vector3.Dot(ab, a), d2 = -Vector3.Dot(ac, a);
            if (d1 <= 0 && d2 <= 0) { Keep1(0); return; }
            float d3 = -Vector3.Dot(ab, b), d4 = -Vector3.Dot(ac, b);
            if (d3 >= 0 && d4 <= d3) { Keep1(1); return; }
            float vc = d1 * d4 - d3 * d2;
            if (vc <= 0 && d1 >= 0 && d3 <= 0) { Keep2(0, 1, d1 / (d1 - d3)); return; }
            float d5 = -Vector3.Dot(ab, c), d6 = -Vector3.Dot(ac, c);
            if (d6 >= 0 && d5 <= d6) { Keep1(2); return; }
            float vb = d5 * d2 - d1 * d6;
            if (vb <= 0 && d2 >= 0 && d6 <= 0) { Keep2(0, 2, d2 / (d2 - d6)); return; }
            float va = d3 * d6 - d5 * d4;
            if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) { Keep2(1, 2, (d4 - d3) / ((d4 - d3) + (d5 - d6))); return; }
            float sum = va + vb + vc;
            if (!(sum > 0)) { SolveDegenerateTriangle(); return; }
            float v = vb / sum, w = vc / sum;
            V0.Weight = 1 - v - w;
            V1.Weight = v;
            V2.Weight = w;
            Count = 3;
        }

        // A collinear triangle: the best of its three edges.
        void SolveDegenerateTriangle()
        {
            Simplex best = default;
            float bestD = float.MaxValue;
            for (int e = 0; e < 3; e++)
            {
                Simplex s = default;
                s.V0 = Get(e);
                s.V1 = Get((e + 1) % 3);
                s.Count = 2;
                s.SolveSegment();
                float d = s.ClosestPoint().LengthSquared();
                if (d < bestD) { bestD = d; best = s; }
            }
            this = best;
        }

        bool SolveTetrahedron()
        {
            // Faces with the opposite vertex: origin outside a face plane means the closest
            // point lies on that face (or its boundary).
            Simplex best = default;
            float bestD = float.MaxValue;
            bool outside = false;
            for (int f = 0; f < 4; f++)
            {
                int i0, i1, i2, opposite;
                switch (f)
                {
                    case 0: i0 = 0; i1 = 1; i2 = 2; opposite = 3; break;
                    case 1: i0 = 0; i1 = 2; i2 = 3; opposite = 1; break;
                    case 2: i0 = 0; i1 = 3; i2 = 1; opposite = 2; break;
                    default: i0 = 1; i1 = 3; i2 = 2; opposite = 0; break;
                }
                Vector3 a = Get(i0).W, n = Vector3.Cross(Get(i1).W - a, Get(i2).W - a);
                float signOrigin = -Vector3.Dot(a, n);
                float signOpposite = Vector3.Dot(Get(opposite).W - a, n);
                float scale = n.LengthSquared();
                // A flat tetrahedron cannot contain the origin: every face is a candidate.
                bool flat = signOpposite * signOpposite <= 1e-10f * scale * MathF.Max(1e-12f, (Get(opposite).W - a).LengthSquared());
                if (!flat && signOrigin * signOpposite >= 0) continue;
                outside = true;
                Simplex s = default;
                s.V0 = Get(i0);
                s.V1 = Get(i1);
                s.V2 = Get(i2);
                s.Count = 3;
                s.SolveTriangle();
                float d = s.ClosestPoint().LengthSquared();
                if (d < bestD) { bestD = d; best = s; }
            }
            if (!outside)
            {
                // Weights of the origin inside: ratios of sub-volumes (not needed by callers,
                // which only ask whether the cores overlap), kept uniform.
                V0.Weight = V1.Weight = V2.Weight = V3.Weight = 0.25f;
                return false;
            }
            this = best;
            return true;
        }

        void Keep1(int i)
        {
            SimplexVertex v = Get(i);
            v.Weight = 1;
            V0 = v;
            Count = 1;
        }

        void Keep2(int i, int j, float t)
        {
            SimplexVertex a = Get(i), b = Get(j);
            a.Weight = 1 - t;
            b.Weight = t;
            V0 = a;
            V1 = b;
            Count = 2;
        }
    }
}
