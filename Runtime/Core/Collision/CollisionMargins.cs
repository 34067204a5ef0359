using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// The one place where Fulcrum's collision margins and skins are decided. Every other
    /// file reads these numbers instead of inventing its own.
    /// <para>
    /// <b>Shapes have no skin.</b> Boxes, hulls and meshes collide with their exact surfaces;
    /// spheres and capsules are a core (a point, a segment) plus a radius. No shape is
    /// inflated or shrunk, so contact points lie on the real surfaces and a box resting on a
    /// box rests at a separation the solver chooses (about -<see cref="WorldSettings.LinearSlop"/>),
    /// not at a hidden gap.
    /// </para>
    /// <para>
    /// <b>Speculative distance.</b> A pair reports contact points while its surfaces are closer
    /// than <c>SpeculativeDistance(slop) + motion bound</c>: <see cref="SpeculativeSlopFactor"/>
    /// times the linear slop (4 x 5 mm = 2 cm by default) plus how far the two bodies can move
    /// towards each other in the step (|v| dt + |w| r dt for each, r the body's reach from its
    /// centre of mass). Points with a positive <see cref="ContactPoint.Separation"/> are
    /// speculative: the solver lets the gap close but not invert, so a fast body meets the
    /// solver before it overlaps (Catto, "Speculative contacts", GDC 2013).
    /// </para>
    /// <para>
    /// <b>Fat bounds.</b> The broad phase stores each moving shape's bounds grown by
    /// <see cref="AabbMargin"/> on every side, around the shape swept over its predicted motion
    /// in the step plus the speculative distance. A proxy is moved in its tree only when the
    /// swept bounds leave the fat box, which keeps tree updates rare for resting and slow
    /// bodies. Static shapes get the same margin once.
    /// </para>
    /// <para>
    /// <b>Touching.</b> For events and statistics a pair touches when a point's separation is at
    /// most <see cref="WorldSettings.LinearSlop"/>, or when the solver pushed on it (a speculative
    /// point that stopped a fast body is a hit).
    /// </para>
    /// <para>
    /// <b>Continuous collision.</b> Time of impact advances until the surfaces are
    /// <see cref="CcdTargetFactor"/> x slop apart, never to exact contact, so the next step's
    /// speculative contact sees a small positive gap rather than an overlap.
    /// </para>
    /// </summary>
    public static class CollisionMargins
    {
        /// <summary>Fat-AABB margin added on every side of a proxy's bounds, metres. 0.1 m.</summary>
        public const float AabbMargin = 0.1f;

        /// <summary>The constant part of the speculative distance, in units of the linear slop. 4.</summary>
        public const float SpeculativeSlopFactor = 4f;

        /// <summary>Target gap of continuous collision, in units of the linear slop. 1.</summary>
        public const float CcdTargetFactor = 1f;

        /// <summary>Distance below which GJK treats two cores as intersecting, metres. 1e-5 m.</summary>
        public const float CoreTolerance = 1e-5f;

        /// <summary>The constant speculative distance for a given linear slop, metres.</summary>
        public static float SpeculativeDistance(float linearSlop) => SpeculativeSlopFactor * linearSlop;

        // The farthest a shape's bounds reach from its body's centre of mass (a rotation at
        // angular speed w moves no point of the shape faster than w times this).
        internal static float Reach(in Aabb box, Vector3 center) => Vector3.Distance(box.Center, center) + box.Extents.Length();
    }
}
