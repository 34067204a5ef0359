using System.Numerics;
using Fulcrum.Scenes;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftScenes
{
    /// <summary>The soft-body stage pushes rigid bodies itself (RigidCoupling): it must honour their axis locks too.</summary>
    public class AxisLockSoftTests
    {
        // box-on-jelly with the 20 kg box moved near the slab's edge, where the dented surface
        // under it is tilted, and allowed to move only up and down: the jelly's pushes have
        // sideways parts, which the locks must drop.
        [Test]
        public void A_box_locked_to_vertical_motion_sinks_into_the_jelly_without_moving_sideways_or_turning()
        {
            SoftSceneRun run = SoftSceneRun.Load("box-on-jelly", doc =>
            {
                SceneBody box = doc.Bodies.Find(b => b.Name == "box")!;
                box.Position = new Vector3(0.38f, 0.75f, 0.3f);
                box.LockAxes = AxisLocks.LinearX | AxisLocks.LinearZ | AxisLocks.Angular;
            });
            BodyHandle h = run.Scene.GetBody("box");
            float lowest = float.MaxValue;
            for (int n = 0, steps = run.StepsIn(1.5f); n < steps; n++)
            {
                run.Step();
                BodyRef b = run.World.GetBody(h);
                Assert.That(b.Position.X, Is.EqualTo(0.38f), $"step {n}");
                Assert.That(b.Position.Z, Is.EqualTo(0.3f), $"step {n}");
                Assert.That(b.Rotation, Is.EqualTo(Quaternion.Identity), $"step {n}");
                lowest = System.MathF.Min(lowest, b.Position.Y);
            }
            Assert.That(run.AllFinite(), Is.True);
            Assert.That(lowest, Is.LessThan(0.705f), "the box came down onto the jelly and pressed it");
            Assert.That(run.World.GetBody(h).Position.Y, Is.GreaterThan(0.55f), "the jelly holds it up");
        }
    }
}
