using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Last step's points of one contact (feature id and accumulated impulses), captured
    /// before its manifolds are rewritten, so each new point can take the impulses of the old
    /// point with the same feature id. A point is taken at most once.
    /// </summary>
    internal sealed class ContactPointCache
    {
        const int Capacity = ContactGraph.MaxManifoldsPerPair * ContactManifold.MaxPoints;
        readonly uint[] _ids = new uint[Capacity];
        readonly float[] _normal = new float[Capacity];
        readonly float[] _tangent1 = new float[Capacity];
        readonly float[] _tangent2 = new float[Capacity];
        readonly bool[] _taken = new bool[Capacity];
        readonly Vector3[] _rolling = new Vector3[ContactGraph.MaxManifoldsPerPair];
        int _count;
        int _manifolds;

        /// <summary>Captures the points of the manifold chain starting at <paramref name="first"/>.</summary>
        public void Capture(ContactGraph graph, int first)
        {
            _count = 0;
            _manifolds = 0;
            for (int m = first; m >= 0 && _manifolds < _rolling.Length; m = graph.ManifoldNext[m])
            {
                ref ContactManifold mf = ref graph.Manifolds[m];
                _rolling[_manifolds++] = mf.RollingImpulse;
                for (int i = 0; i < mf.PointCount; i++)
                {
                    ref ContactPoint p = ref ContactManifold.Point(ref mf, i);
                    _ids[_count] = p.FeatureId;
                    _normal[_count] = p.NormalImpulse;
                    _tangent1[_count] = p.TangentImpulse1;
                    _tangent2[_count] = p.TangentImpulse2;
                    _taken[_count] = false;
                    _count++;
                }
            }
        }

        /// <summary>The old impulses of the point with this feature id; false (and zeros) when there was none.</summary>
        public bool TryTake(uint id, out float normal, out float tangent1, out float tangent2)
        {
            for (int i = 0; i < _count; i++)
            {
                if (_taken[i] || _ids[i] != id) continue;
                _taken[i] = true;
                normal = _normal[i];
                tangent1 = _tangent1[i];
                tangent2 = _tangent2[i];
                return true;
            }
            normal = tangent1 = tangent2 = 0;
            return false;
        }

        /// <summary>The old rolling impulse of manifold <paramref name="index"/> in the chain (zero if none).</summary>
        public Vector3 RollingImpulse(int index) => index < _manifolds ? _rolling[index] : Vector3.Zero;
    }
}
