using Fulcrum.Collision;
using NUnit.Framework;

namespace Fulcrum.Tests.Collision
{
    /// <summary>ContactManifold.Point, the by-index view of the four point fields.</summary>
    public class ContactManifoldPointTests
    {
        [Test]
        public void Point_i_is_the_field_Point_i_and_out_of_range_indices_give_point_3()
        {
            var m = new ContactManifold();
            m.Point0.Separation = 10;
            m.Point1.Separation = 11;
            m.Point2.Separation = 12;
            m.Point3.Separation = 13;
            for (int i = 0; i < 4; i++)
                Assert.That(ContactManifold.Point(ref m, i).Separation, Is.EqualTo(10 + i));
            // The same storage, not a copy: a write through Point(2) shows in Point2.
            ContactManifold.Point(ref m, 2).Separation = 42;
            Assert.That(m.Point2.Separation, Is.EqualTo(42f));
            Assert.That(ContactManifold.Point(ref m, 4).Separation, Is.EqualTo(13f));
            Assert.That(ContactManifold.Point(ref m, -1).Separation, Is.EqualTo(13f));
            ContactManifold.Point(ref m, 1).FeatureId = 77;
            Assert.That(m.Point1.FeatureId, Is.EqualTo(77u));
        }
    }
}
