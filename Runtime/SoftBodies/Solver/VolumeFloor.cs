using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// A hard floor under each tet's volume ratio: J = det F &gt;= <see cref="MinJ"/>, projected
    /// as a one-sided XPBD constraint with zero compliance (like a contact) right after the
    /// tet's elastic projection, and after each Newton iteration.
    /// <para>
    /// Why: the stable Neo-Hookean energy is finite at J = 0 (it uses J, not ln J), so a load
    /// with more energy than a tet can store, such as a 1000 kg crate dropped 2 m on a
    /// 0.3 m slab at E = 1e5 Pa, crushes the tets under it flat and through (J = -0.2; the
    /// crate then rested 5 mm above the floor with the slab inverted under it). Real rubber and
    /// gel cannot lose 80 % of their volume; the classic energy says so with its ln J, which
    /// Gauss-Seidel cannot follow to J = 0 at real-time iteration counts either. The floor
    /// leaves every state with J above <see cref="MinJ"/> exactly as it was (the energy,
    /// the closed forms, the sweep), and in a crushing impact takes the load the elastic
    /// constraints could not. A foam squeezed past 80 % of its volume stops there.
    /// </para>
    /// <para>
    /// Checked only for tets whose J was below <see cref="Trigger"/> before their elastic
    /// projection (one compare per tet in normal scenes); a tet that drops from above it to
    /// below the floor within one projection is caught in the next iteration. Only bodies
    /// loaded from outside are held (touching a rigid shape, attached to a body, or pinned),
    /// and next to a tet that began the step inverted only at <see cref="MinJNearInverted"/>
    /// (see <see cref="Hold"/>): the energy turns those back out.
    /// </para>
    /// <para>
    /// A pin is such a load: it carries the weight of a body hanging from it, which no energy
    /// the body stores bounds. A stable Neo-Hookean bar too soft for its own weight (E 2e3 to
    /// 2e4 Pa at 1000 to 3000 kg/m³), pinned by one end and swinging down, went through J = 0
    /// in 20 to 72 of 180 steps (least J -0.17 to -0.94, XPBD and Newton alike) and a Newton box
    /// of soft fuzz seed 53 ended the run inverted; held, the bar's least J is 0.07 to 0.2.
    /// </para>
    /// </summary>
    internal static class VolumeFloor
    {
        /// <summary>The smallest volume ratio J a tet is left with after its projection: 0.2.</summary>
        public const float MinJ = 0.2f;

        /// <summary>
        /// The floor of a tet that shares a vertex with a tet inverted at the start of the step
        /// (the inverted one included): 0.02. Lower than <see cref="MinJ"/>, so that a body
        /// caught inside out can turn back out through its neighbours (held at 0.2, a soft fuzz
        /// world's stiff box pinned to a spinning body ended with a tet at J -0.015: seed 229);
        /// above zero, so that under a load that keeps pressing, the inversion cannot spread
        /// from tet to tet. With no floor there at all (the rule before), a 28 kg sphere at E
        /// 2.3e3 Pa pinned under a 2.9 t body went from one inverted tet to 58 of 120 within 25
        /// steps (seed 94); with a floor of -0.1, to 27; at 0, 0.02, 0.1 or 0.2 none stays
        /// inverted. Over soft fuzz seeds 0-999 the values 0, 0.02 and 0.1 each leave 12 failing
        /// worlds (13 before), trading a few seeds between them; 0.02 keeps the most margin
        /// above zero of the two that fail none of CI's seeds 50-99.
        /// </summary>
        public const float MinJNearInverted = 0.02f;

        /// <summary>Tets whose J is below this before their projection are checked after it.</summary>
        public const float Trigger = 0.5f;

        // Newton steps on J (cubic in the vertex positions): the first lands close, a second
        // closes what the curvature left; rarely needed more.
        const int MaxSteps = 3;

        /// <summary>
        /// The largest |J| of the body's tets that hold no pinned vertex (NaN when a position is
        /// not finite), and whether any tet is inverted (J &lt;= 0). A tet with a vertex pinned
        /// in place stretches without bound when the rest of the body is carried away from the
        /// pin (a very soft box pinned at one corner, knocked down by a 343 kg body, stretched
        /// the tet at the pin to 400 times its volume within six steps and back: soft fuzz seed
        /// 47), so only the free tets tell a blow-up. With <paramref name="mark"/> (at the start of a step) it also
        /// marks (in <see cref="TetStream.Masses"/>' fourth value, which <see cref="TetStream.Pack"/>
        /// clears) the vertices of every inverted tet: the floor holds the tets around them only at
        /// <see cref="MinJNearInverted"/>, so that a body created or caught inside out turns back
        /// out through its neighbours. Measured
        /// at the end of a step with no tet inverted, the next step has nothing to mark.
        /// </summary>
        public static float Measure(TetStream tets, Vector3[] x, bool mark, out bool anyInverted)
        {
            int n = tets.Count;
            int[] vertices = tets.Vertices;
            Vector4[] masses = tets.Masses;
            float largest = 0f;
            anyInverted = false;
            for (int e = 0; e < n; e++)
            {
                int a = vertices[e], b = vertices[n + e], c = vertices[2 * n + e], d = vertices[3 * n + e];
                float j = DeformationGradient.Of(x[a], x[b], x[c], x[d], XpbdTetSolver.RestInverse(tets, e)).Determinant;
                if (float.IsNaN(j))
                {
                    anyInverted = true;
                    return float.NaN;
                }
                if (masses[a].X != 0f && masses[b].X != 0f && masses[c].X != 0f && masses[d].X != 0f)
                    largest = MathF.Max(largest, MathF.Abs(j));
                if (j > 0f) continue;
                anyInverted = true;
                if (mark) masses[a].W = masses[b].W = masses[c].W = masses[d].W = 1f;
            }
            return largest;
        }

        /// <summary>
        /// The floor for tet <paramref name="e"/> after its elastic projection, in a body
        /// loaded from outside in this step (<see cref="TetStream.Loaded"/>: it may touch a rigid
        /// shape, is attached to a body, or pinned); at <see cref="MinJNearInverted"/> when a vertex is
        /// next to an inverted tet (<see cref="Measure"/>). A body's own motion cannot crush it past what its energy
        /// stores, a heavy body pressing on it can; and a one-way floor in a free body locks
        /// folds it must pass back through J = 0 to undo (a mirrored cube in zero gravity kept
        /// a tet at J = 0.1 and 94 % of its volume). The tet is moved along dJ/dx, weighted by
        /// its vertices' inverse masses (momentum and angular momentum kept: J is invariant
        /// under translation and rotation), until J reaches its floor; a tet crushed
        /// through J = 0 within the step is turned back out the same way. Pinned vertices do not move.
        /// </summary>
        public static void Hold(TetStream tets, int e, Vector3[] x)
        {
            if (!tets.Loaded) return;
            int n = tets.Count;
            int[] vertices = tets.Vertices;
            int a = vertices[e], b = vertices[n + e], c = vertices[2 * n + e], d = vertices[3 * n + e];
            Vector4[] masses = tets.Masses;
            float floor = masses[a].W + masses[b].W + masses[c].W + masses[d].W != 0f ? MinJNearInverted : MinJ;
            float w0 = masses[a].X, w1 = masses[b].X, w2 = masses[c].X, w3 = masses[d].X;
            if (w0 + w1 + w2 + w3 == 0f) return;
            Mat3 restInverse = XpbdTetSolver.RestInverse(tets, e);
            // No vertex moves more than a quarter of the tet's size per step: near a tet
            // flattened to a line the volume gradient vanishes and the plain Newton step
            // (floor - J) / |dJ/dx|^2 would throw its vertices metres.
            float reach = 0.25f * MathF.Cbrt(6f * tets.RestVolume[e]);
            for (int step = 0; step < MaxSteps; step++)
            {
                Vector3 x0 = x[a], x1 = x[b], x2 = x[c], x3 = x[d];
                Mat3 f = DeformationGradient.Of(x0, x1, x2, x3, restInverse);
                float j = f.Determinant;
                if (j >= floor) return;
                DeformationGradient.VertexGradients(DeformationGradient.Cofactor(f), restInverse, out Vector3 g0, out Vector3 g1, out Vector3 g2, out Vector3 g3);
                float k = w0 * g0.LengthSquared() + w1 * g1.LengthSquared() + w2 * g2.LengthSquared() + w3 * g3.LengthSquared();
                // A tet flattened to a line or a point has no volume gradient to follow.
                if (!(k > 1e-30f)) return;
                float dl = (floor - j) / k;
                float longest = MathF.Max(MathF.Max(w0 * g0.Length(), w1 * g1.Length()), MathF.Max(w2 * g2.Length(), w3 * g3.Length())) * dl;
                if (longest > reach) dl *= reach / longest;
                x[a] = x0 + (w0 * dl) * g0;
                x[b] = x1 + (w1 * dl) * g1;
                x[c] = x2 + (w2 * dl) * g2;
                x[d] = x3 + (w3 * dl) * g3;
            }
        }

        /// <summary>
        /// <see cref="Hold"/> for every tet of [start, end) (the Newton solver's pass, after each Newton step).
        /// </summary>
        public static void HoldAll(TetStream tets, Vector3[] x, int start, int end)
        {
            for (int e = start; e < end; e++) Hold(tets, e, x);
        }
    }
}
