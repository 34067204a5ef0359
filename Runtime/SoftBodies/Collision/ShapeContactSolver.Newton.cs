using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// What a Newton body's step asks of its contacts: the vertices it meets with springs, their
    /// support, and the sticks that hold resting vertices inside the step.
    /// </summary>
    internal sealed partial class ShapeContactSolver
    {
        /// <summary>
        /// Records that the Newton solver's step met vertex <paramref name="i"/> against the
        /// dynamic body in <paramref name="slot"/> (normal and friction): the contact pass leaves
        /// that pair alone in this substep.
        /// </summary>
        public void MetByNewton(int i, int slot) => _newtonOwner[i] = slot + 1;

        /// <summary>
        /// Records the normal impulse (kg m) that a Newton step's spring against an immovable
        /// shape carried at vertex <paramref name="i"/> (the largest over the first iteration's
        /// steps; a later step's report replaces it, see <see cref="ReplaceSupport"/>):
        /// friction is bounded by mu times it as by the contact pass's own normal
        /// corrections. The springs hold a Newton body's vertices at the ground inside the step,
        /// so the pass after it had almost no normal correction left to bound friction by, and a
        /// Newton slab pushed at 1 m/s across the ground slid on at 0.99 m/s after 2 s.
        /// </summary>
        public void Support(int i, float impulse)
        {
            if (_supportReplaced)
            {
                Array.Clear(_support, 0, _support.Length);
                _supportReplaced = false;
            }
            if (impulse > _support[i]) _support[i] = impulse;
        }

        /// <summary>
        /// Starts a Newton step after the substep's first iteration: the supports it reports
        /// replace those recorded so far (a step that reports none, having converged or found no
        /// descent, leaves them). Each step measures the substep's whole normal impulse from its
        /// start, spread over the vertices by that step's springs; the largest per vertex over two
        /// steps whose springs held different vertices summed to up to twice the body's weight,
        /// and a Newton cube at two iterations held on every slope it should have slid down
        /// (friction 24 % above mu; keeping the largest over the steps within each iteration, it
        /// still slid up to 150 % slow). In the first iteration the largest of its steps stands
        /// (the step that follows a vertex entering a shape): replaced there too, at one iteration,
        /// soft fuzz seed 47 failed newly.
        /// </summary>
        public void ReplaceSupport() => _supportReplaced = true;

        /// <summary>
        /// True when vertex <paramref name="i"/> was within reach of an immovable shape in the last
        /// substep while its body was at rest (<see cref="HoldPatch"/>), with the shape's normal
        /// and the velocity of its surface there: the Newton step holds it across the normal
        /// (ImplicitNewtonSolver.Stick) and reports the friction that took (<see cref="Stuck"/>),
        /// which <see cref="CapSticks"/> holds to the patch's cone.
        /// </summary>
        public bool Sticks(int i, out Vector3 normal, out Vector3 surfaceVelocity)
        {
            bool sticks = i < _restLast.Length && _restLast[i];
            normal = sticks ? _restNormalLast[i] : Vector3.Zero;
            surfaceVelocity = sticks ? _restVelocityLast[i] : Vector3.Zero;
            return sticks;
        }

        /// <summary>The friction impulse (kg m, along the way the vertex was pulled) the Newton step's sticking spring carried at vertex <paramref name="i"/> in this substep.</summary>
        public void Stuck(int i, Vector3 impulse) => _stick[i] = impulse;

        /// <summary>True (with its normal) when an immovable shape pushed vertex <paramref name="i"/> in this substep or the last.</summary>
        public bool Touches(int i, out Vector3 normal)
        {
            normal = i < _normal.Length ? _normal[i] : default;
            return i < _holdNow.Length && (_holdNow[i] || _holdLast[i]);
        }
    }
}
