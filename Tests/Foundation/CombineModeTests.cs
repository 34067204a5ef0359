using NUnit.Framework;

namespace Fulcrum.Tests.Foundation
{
    /// <summary>
    /// CombineMode has Unity's numbers (PhysicsMaterialCombine: Average 0, Multiply 1, Minimum 2,
    /// Maximum 3), so a value cast from Unity means the same, and Unity's precedence when two
    /// shapes disagree (Average &lt; Minimum &lt; Multiply &lt; Maximum).
    /// </summary>
    public class CombineModeTests
    {
        [Test]
        public void The_numbers_are_unitys()
        {
            Assert.That((int)CombineMode.Average, Is.EqualTo(0));
            Assert.That((int)CombineMode.Multiply, Is.EqualTo(1));
            Assert.That((int)CombineMode.Minimum, Is.EqualTo(2));
            Assert.That((int)CombineMode.Maximum, Is.EqualTo(3));
        }

        [TestCase(CombineMode.Average, CombineMode.Minimum, 0.2f)]
        [TestCase(CombineMode.Minimum, CombineMode.Multiply, 0.08f)]
        [TestCase(CombineMode.Multiply, CombineMode.Maximum, 0.4f)]
        [TestCase(CombineMode.Maximum, CombineMode.Average, 0.4f)]
        [TestCase(CombineMode.Average, CombineMode.Average, 0.3f)]
        public void The_mode_of_higher_precedence_wins_whichever_side_asks(CombineMode a, CombineMode b, float expected)
        {
            Assert.That(Combine.Values(0.2f, a, 0.4f, b), Is.EqualTo(expected).Within(1e-6f));
            Assert.That(Combine.Values(0.4f, b, 0.2f, a), Is.EqualTo(expected).Within(1e-6f));
        }
    }
}
