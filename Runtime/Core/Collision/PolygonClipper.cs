using System;
using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Sutherland-Hodgman clipping of an incident face polygon against the side planes of a
    /// reference face, tracking for every output vertex a key that names the features that
    /// made it, so the same contact point gets the same key next step:
    /// an incident vertex k keeps key k; a crossing of segment s with side plane p gets
    /// <c>0x8000 | s &lt;&lt; 8 | p</c>, where s is the incident edge it lies on (0..127) or
    /// 128 + the side plane it runs along (for a segment created by an earlier cut).
    /// Each vertex also carries the code of the segment leaving it.
    /// </summary>
    internal static class PolygonClipper
    {
        /// <summary>The most vertices a clipped polygon may have (incident face plus side planes).</summary>
        public const int MaxVertices = 64;

        /// <summary>
        /// Clips <paramref name="points"/>[0, count) in place against planes
        /// dot(n_p, x) &lt;= d_p; returns the new count. Keys start as vertex indices and
        /// segment codes as edge indices (set by the caller). A vertex at most
        /// <paramref name="tolerance"/> outside a plane counts as inside and is kept as it is
        /// (with its key); crossings are still cut at the exact plane. So a corner lying on a
        /// side plane (equal boxes stacked flush) keeps its feature id from step to step instead
        /// of flipping between kept and clipped, which would lose its warm-start impulse.
        /// </summary>
        public static int Clip(Span<Vector3> points, Span<uint> keys, Span<uint> segments, int count,
            ReadOnlySpan<Vector3> planeNormals, ReadOnlySpan<float> planeOffsets,
            Span<Vector3> scratchPoints, Span<uint> scratchKeys, Span<uint> scratchSegments, float tolerance = 0)
        {
            // Ping-pong between the two buffers; one copy at the end if the result landed in
            // the scratch ones (an odd number of planes).
            Span<Vector3> inPoints = points, outPoints = scratchPoints;
            Span<uint> inKeys = keys, outKeys = scratchKeys, inSegments = segments, outSegments = scratchSegments;
            bool swapped = false;
            for (int p = 0; p < planeNormals.Length && count > 0; p++)
            {
                count = ClipOne(inPoints, inKeys, inSegments, count, planeNormals[p], planeOffsets[p], (uint)p, tolerance,
                    outPoints, outKeys, outSegments);
                Span<Vector3> tp = inPoints; inPoints = outPoints; outPoints = tp;
                Span<uint> tk = inKeys; inKeys = outKeys; outKeys = tk;
                Span<uint> ts = inSegments; inSegments = outSegments; outSegments = ts;
                swapped = !swapped;
            }
            if (swapped && count > 0)
            {
                inPoints.Slice(0, count).CopyTo(points);
                inKeys.Slice(0, count).CopyTo(keys);
                inSegments.Slice(0, count).CopyTo(segments);
            }
            return count;
        }

        static int ClipOne(ReadOnlySpan<Vector3> pts, ReadOnlySpan<uint> keys, ReadOnlySpan<uint> segs, int count,
            Vector3 normal, float offset, uint plane, float tolerance,
            Span<Vector3> outPts, Span<uint> outKeys, Span<uint> outSegs)
        {
            int written = 0;
            int limit = outPts.Length;
            // Each vertex's distance is computed once and handed on to the next edge.
            float d0 = Vector3.Dot(normal, pts[0]) - offset;
            float dn = d0;
            for (int k = 0; k < count; k++)
            {
                int next = k + 1 == count ? 0 : k + 1;
                Vector3 cur = pts[k], nxt = pts[next];
                float dc = dn;
                dn = next == 0 ? d0 : Vector3.Dot(normal, nxt) - offset;
                bool curIn = dc <= tolerance, nextIn = dn <= tolerance;
                if (curIn && written < limit)
                {
                    outPts[written] = cur;
                    outKeys[written] = keys[k];
                    outSegs[written] = segs[k];
                    written++;
                }
                // A vertex inside only by the tolerance stands for the crossing itself.
                if (curIn != nextIn && (curIn ? dc <= 0 : dn <= 0) && written < limit)
                {
                    float t = dc / (dc - dn);
                    outPts[written] = cur + t * (nxt - cur);
                    outKeys[written] = 0x8000u | ((segs[k] & 0xFFu) << 8) | (plane & 0xFFu);
                    // Leaving the half-space, the new segment runs along the plane; entering
                    // it, it continues along the segment being cut.
                    outSegs[written] = curIn ? 128u + plane : segs[k];
                    written++;
                }
            }
            return written;
        }
    }
}
