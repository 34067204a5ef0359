using System;
using Fulcrum.Components;
using NUnit.Framework;

namespace Fulcrum.Tests.Foundation
{
    /// <summary>
    /// The five public handle types share one core (slot, generation, world id): the same "none",
    /// equality (world id left out), hash and text for each.
    /// </summary>
    public class HandleShapeTests
    {
        static void Check<T>(Func<int, int, int, T> make, Func<int, int, T> noWorld, Func<T, bool> isNone, string name)
            where T : struct, IEquatable<T>
        {
            T a = make(3, 2, 7);
            Assert.That(a.ToString(), Is.EqualTo(name + "(3:2 of world 7)"));
            Assert.That(default(T).ToString(), Is.EqualTo(name + "(none)"));
            Assert.That(isNone(default), Is.True);
            Assert.That(isNone(a), Is.False);
            Assert.That(isNone(make(3, 0, 7)), Is.True, "generation 0 is none whatever the slot");
            Assert.That(a.Equals(make(3, 2, 8)), Is.True, "the world id is left out of equality");
            Assert.That(a.GetHashCode(), Is.EqualTo(make(3, 2, 8).GetHashCode()));
            Assert.That(a.Equals(make(3, 1, 7)), Is.False, "another generation");
            Assert.That(a.Equals(make(4, 2, 7)), Is.False, "another slot");
            Assert.That(a.Equals((object)make(3, 2, 7)), Is.True);
            Assert.That(a.Equals((object)3), Is.False);
            Assert.That(noWorld(3, 2).ToString(), Is.EqualTo(name + "(3:2 of world 0)"), "built with no world id");
        }

        [Test]
        public void Body_shape_joint_soft_body_and_proxy_handles_behave_alike()
        {
            Check((i, g, w) => new BodyHandle(i, g, w), (i, g) => new BodyHandle(i, g), h => h.IsNone, nameof(BodyHandle));
            Check((i, g, w) => new ShapeHandle(i, g, w), (i, g) => new ShapeHandle(i, g), h => h.IsNone, nameof(ShapeHandle));
            Check((i, g, w) => new JointHandle(i, g, w), (i, g) => new JointHandle(i, g), h => h.IsNone, nameof(JointHandle));
            Check((i, g, w) => new SoftBodyHandle(i, g, w), (i, g) => new SoftBodyHandle(i, g), h => h.IsNone, nameof(SoftBodyHandle));
            Check((i, g, w) => new ProxyHandle(i, g, w), (i, g) => new ProxyHandle(i, g), h => h.IsNone, nameof(ProxyHandle));
        }

        [Test]
        public void Handle_fields_read_back_what_they_were_built_with_and_operators_follow_Equals()
        {
            var b = new BodyHandle(5, 9, 2);
            Assert.That((b.Index, b.Generation, b.WorldId), Is.EqualTo((5, 9, 2)));
            var p = new ProxyHandle(5, 9, 2);
            Assert.That((p.Index, p.Generation, p.WorldId), Is.EqualTo((5, 9, 2)));
            Assert.That(b == new BodyHandle(5, 9, 3), Is.True);
            Assert.That(b != new BodyHandle(5, 8, 2), Is.True);
            Assert.That(p == new ProxyHandle(5, 9), Is.True);
            Assert.That(p != new ProxyHandle(6, 9, 2), Is.True);
        }
    }
}
