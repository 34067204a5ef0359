namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// How a soft body's elastic energy is solved in each substep (see Documentation~/SoftSolvers.md
    /// for what each costs and how close it gets to the converged answer).
    /// </summary>
    public enum SoftSolver : byte
    {
        /// <summary>
        /// Extended position-based dynamics (Macklin et al. 2016): one constraint pair per tet,
        /// Gauss-Seidel by colour, on several threads. Cheap per iteration and robust, but a stiff
        /// material converges slowly: its multipliers restart every substep, so an under-iterated
        /// stiff body is much softer than its material.
        /// </summary>
        Xpbd = 0,

        /// <summary>
        /// Implicit Euler with Newton steps solved directly over the whole body
        /// (<see cref="ImplicitNewtonSolver"/>): a load crosses a stiff body in one solve, so a
        /// stiff material reaches its converged answer where XPBD is far too soft (a 1 m
        /// cantilever at E = 1e9 Pa). Costs O(n b^2) per iteration for n vertices and a mesh band
        /// b: for small and medium bodies. Tetrahedral bodies only; one substep per step unless
        /// the body asks for more; one thread.
        /// </summary>
        Newton = 1,
    }
}
