using System;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// A dense spatial hash of points: cells of a given size hashed into a table of about
    /// twice as many entries as points, filled by counting sort (no per-cell lists, nothing
    /// allocated after construction). Hash collisions only add candidates; callers test distance.
    /// </summary>
    internal sealed class SpatialHash
    {
        readonly int[] _cellStart;
        readonly int[] _entries;
        readonly int _tableSize;
        float _invCell;

        public SpatialHash(int maxPoints)
        {
            _tableSize = Math.Max(16, 2 * maxPoints);
            _cellStart = new int[_tableSize + 1];
            _entries = new int[Math.Max(1, maxPoints)];
        }

        /// <summary>Hashes <paramref name="points"/>[ids[k]] for k &lt; count into cells of <paramref name="cellSize"/> metres.</summary>
        public void Build(Vector3[] points, int[] ids, int count, float cellSize)
        {
            _invCell = 1f / cellSize;
            Array.Clear(_cellStart, 0, _cellStart.Length);
            for (int k = 0; k < count; k++) _cellStart[Hash(points[ids[k]])]++;
            int sum = 0;
            for (int c = 0; c < _tableSize; c++)
            {
                sum += _cellStart[c];
                _cellStart[c] = sum;
            }
            _cellStart[_tableSize] = sum;
            for (int k = 0; k < count; k++) _entries[--_cellStart[Hash(points[ids[k]])]] = ids[k];
        }

        /// <summary>The hash-table cell of a point.</summary>
        public int Hash(Vector3 p) => HashCell(Floor(p.X * _invCell), Floor(p.Y * _invCell), Floor(p.Z * _invCell));

        /// <summary>The cell coordinates of a point.</summary>
        public void Cell(Vector3 p, out int x, out int y, out int z)
        {
            x = Floor(p.X * _invCell);
            y = Floor(p.Y * _invCell);
            z = Floor(p.Z * _invCell);
        }

        /// <summary>The table cell of integer cell coordinates (Teschner et al. 2003 hash).</summary>
        public int HashCell(int x, int y, int z)
        {
            int h = (x * 92837111) ^ (y * 689287499) ^ (z * 283923481);
            return (int)((uint)h % (uint)_tableSize);
        }

        /// <summary>The entries of table cell <paramref name="cell"/> are <c>Entry(Start(cell)) .. Entry(Start(cell + 1) - 1)</c>.</summary>
        public int Start(int cell) => _cellStart[cell];

        /// <summary>A point id stored in the table.</summary>
        public int Entry(int k) => _entries[k];

        static int Floor(float v) => (int)MathF.Floor(v);
    }
}
