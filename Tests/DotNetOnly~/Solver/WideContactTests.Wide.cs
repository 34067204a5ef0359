using System;
using System.Numerics;
using Fulcrum;
using NUnit.Framework;
using static Fulcrum.Tests.Solver.SolverTestScenes;

namespace Fulcrum.Tests.Solver
{
    // The wide (SIMD) contact path is compiled only for .NET (#if NET): a netstandard2.1 build,
    // Unity's, has the scalar path alone, so this comparison is net10 only (this folder ends in
    // '~', so Unity never compiles it); the rest of WideContactTests is in Tests/Solver.
    public partial class WideContactTests
    {
        [Test]
        public void Wide_and_scalar_contact_paths_agree_on_a_pyramid()
        {
            var (scalar, none) = Pyramid(false);
            var (wide, groups) = Pyramid(true);
            Assert.That(none, Is.EqualTo(0));
            if (!System.Numerics.Vector.IsHardwareAccelerated) Assert.Ignore("no SIMD hardware: the scalar path runs alone");
            Assert.That(groups, Is.GreaterThan(10), "four-point manifolds went to the wide path");
            float worst = 0;
            for (int i = 0; i < scalar.Length; i++) worst = MathF.Max(worst, Vector3.Distance(scalar[i], wide[i]));
            TestContext.Out.WriteLine($"largest position difference after 1.5 s: {worst:E2} m");
            Assert.That(worst, Is.LessThan(1e-4f));
        }
    }
}
