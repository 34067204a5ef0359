namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// A <see cref="RangeJob"/> over one element family of a soft body (tets, membrane
    /// triangles, bending hinges): the position solve of a substep, or with
    /// <see cref="Damping"/> its velocity damping pass. One job per family and body is kept
    /// and re-aimed with <see cref="For"/> before each pass, so a step allocates nothing.
    /// </summary>
    internal abstract class ElementRangeJob : RangeJob
    {
        /// <summary>The body whose elements the job solves.</summary>
        protected readonly SoftBody Body;

        /// <summary>The substep, s.</summary>
        protected float H;

        /// <summary>The body's <see cref="SoftBody.DampingTime"/>, s, in this pass.</summary>
        protected float DampingTime;

        /// <summary>Whether this pass is the damping pass rather than the position solve.</summary>
        protected bool Damping;

        protected ElementRangeJob(SoftBody body) => Body = body;

        /// <summary>Sets the pass the next <see cref="RangeJob.Execute"/> calls run; returns the job.</summary>
        public ElementRangeJob For(float h, float dampingTime, bool damping)
        {
            H = h;
            DampingTime = dampingTime;
            Damping = damping;
            return this;
        }
    }
}
