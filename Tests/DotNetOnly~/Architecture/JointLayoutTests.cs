using System;
using System.Linq;
using System.Runtime.CompilerServices;
using Fulcrum.Dynamics;
using NUnit.Framework;

namespace Fulcrum.Tests.Architecture
{
    /// <summary>
    /// The joint kinds' constraint parts are overlaid: a joint is as large as the common header
    /// plus its largest kind's block, not all kinds' parts together.
    /// </summary>
    public class JointLayoutTests
    {
        [Test]
        public void Kind_blocks_overlay_each_other()
        {
            int[] blocks =
            {
                Unsafe.SizeOf<BallJointParts>(), Unsafe.SizeOf<HingeJointParts>(), Unsafe.SizeOf<DistanceJointParts>(),
                Unsafe.SizeOf<FixedJointParts>(), Unsafe.SizeOf<PrismaticJointParts>(), Unsafe.SizeOf<ConeTwistJointParts>(),
            };
            TestContext.Out.WriteLine($"JointData {Unsafe.SizeOf<JointData>()} B, parts {Unsafe.SizeOf<JointParts>()} B, kinds {string.Join(", ", blocks)}");
            Assert.That(Unsafe.SizeOf<JointParts>(), Is.EqualTo(blocks.Max()));
            // Before the overlay: 744 B, of which 480 B were the parts of all kinds side by side
            // and 264 B the header; now the header plus the largest block, up to 8 B of padding.
            Assert.That(Unsafe.SizeOf<JointData>(), Is.LessThanOrEqualTo(264 + blocks.Max() + 8));
        }
    }
}
