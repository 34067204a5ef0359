using System.Numerics;
using NUnit.Framework;

namespace Fulcrum.Tests.Foundation
{
    /// <summary>World.StopThreads: the workers end, and a later step starts new ones with the same results.</summary>
    public class StopThreadsTests
    {
        static World Stack(out BodyHandle top)
        {
            WorldSettings s = WorldSettings.Default;
            s.Threads = 2;
            var w = new World(s);
            BodyHandle g = w.CreateBody(BodyDef.Static(new Vector3(0, -0.5f, 0)));
            w.AddShape(g, ShapeDef.Of(ShapeGeometry.Box(new Vector3(10, 0.5f, 10))));
            top = default;
            for (int i = 0; i < 8; i++)
            {
                BodyDef d = BodyDef.Default;
                d.Position = new Vector3(0.01f * i, 0.5f + i, 0);
                top = w.CreateBody(d);
                w.AddShape(top, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            }
            return w;
        }

        [Test]
        public void Stopping_the_threads_between_steps_changes_no_result()
        {
            World a = Stack(out BodyHandle topA), b = Stack(out BodyHandle topB);
            for (int k = 0; k < 60; k++)
            {
                a.Step(1f / 60f);
                b.Step(1f / 60f);
                if (k == 1) Assert.That(b.SolverPoolForTests, Is.Not.Null, "the step after a stop started new workers");
                if (k % 10 == 0)
                {
                    b.StopThreads();
                    Assert.That(b.SolverPoolForTests, Is.Null, "the pool is gone");
                }
            }
            Assert.That(b.GetBody(topB).Position, Is.EqualTo(a.GetBody(topA).Position), "bit for bit");
            b.StopThreads();
            b.StopThreads();
        }
    }
}
