using System.Runtime.CompilerServices;
using Fulcrum.Dynamics;
using NUnit.Framework;

namespace Fulcrum.Tests.Solver
{
    /// <summary>Sizes of the solver's hot structs, as their doc comments state.</summary>
    public class SolverDataTests
    {
        [Test]
        public void Hot_solver_structs_have_their_documented_sizes()
        {
            Assert.That(Unsafe.SizeOf<SolverBody>(), Is.EqualTo(96));
            Assert.That(Unsafe.SizeOf<ContactRow>(), Is.EqualTo(56));
            Assert.That(Unsafe.SizeOf<ContactConstraintPoint>(), Is.EqualTo(80));
        }
    }
}
