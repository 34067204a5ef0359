using System;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Vertex-vertex self-collision of the surface vertices: each vertex is a sphere of the
    /// body's collision radius r. Once per step a spatial hash finds the pairs that can come
    /// within 2r during the step; each substep pushes such pairs apart to 2r (zero compliance,
    /// split by inverse mass). Pairs closer than 3r in the rest shape are neighbours, never contacts.
    /// </summary>
    internal sealed class SelfCollision
    {
        readonly int[] _ids;
        readonly Vector3[] _rest;
        readonly SpatialHash _hash;
        readonly float _radius;
        int[] _pairs = Array.Empty<int>();
        int _pairCount;

        public SelfCollision(SoftMesh mesh, float radius)
        {
            _radius = Math.Max(radius, 1e-6f);
            _rest = mesh.VertexArray;
            _ids = mesh.SurfaceVertices();
            _hash = new SpatialHash(_ids.Length);
        }

        /// <summary>Pairs found for this step.</summary>
        public int PairCount => _pairCount;

        public void FindPairs(Vector3[] x, Vector3[] v, float dt)
        {
            float maxSpeed2 = 0;
            foreach (int i in _ids) maxSpeed2 = MathF.Max(maxSpeed2, v[i].LengthSquared());
            float reach = 2f * _radius + 2f * MathF.Sqrt(maxSpeed2) * dt;
            _hash.Build(x, _ids, _ids.Length, reach);
            float exclude2 = 9f * _radius * _radius;
            _pairCount = 0;
            foreach (int i in _ids)
            {
                _hash.Cell(x[i], out int cx, out int cy, out int cz);
                for (int dz = -1; dz <= 1; dz++)
                    for (int dy = -1; dy <= 1; dy++)
                        for (int dx = -1; dx <= 1; dx++)
                        {
                            int cell = _hash.HashCell(cx + dx, cy + dy, cz + dz);
                            for (int k = _hash.Start(cell); k < _hash.Start(cell + 1); k++)
                            {
                                int j = _hash.Entry(k);
                                if (j <= i) continue;
                                // A table cell may hold several grid cells; count each pair from its own cell only.
                                _hash.Cell(x[j], out int jx, out int jy, out int jz);
                                if (jx != cx + dx || jy != cy + dy || jz != cz + dz) continue;
                                if ((x[j] - x[i]).LengthSquared() > reach * reach) continue;
                                if ((_rest[j] - _rest[i]).LengthSquared() < exclude2) continue;
                                if (2 * _pairCount + 2 > _pairs.Length) Array.Resize(ref _pairs, Math.Max(64, 2 * _pairs.Length));
                                _pairs[2 * _pairCount] = i;
                                _pairs[2 * _pairCount + 1] = j;
                                _pairCount++;
                            }
                        }
            }
        }

        public void Solve(Vector3[] x, float[] w)
        {
            float minDistance = 2f * _radius;
            for (int p = 0; p < _pairCount; p++)
            {
                int i = _pairs[2 * p], j = _pairs[2 * p + 1];
                float wi = w[i], wj = w[j];
                if (wi + wj == 0f) continue;
                Vector3 d = x[i] - x[j];
                float length = d.Length();
                if (length >= minDistance || length < 1e-9f) continue;
                Vector3 n = d / length;
                float dl = (minDistance - length) / (wi + wj);
                x[i] += wi * dl * n;
                x[j] -= wj * dl * n;
            }
        }
    }
}
