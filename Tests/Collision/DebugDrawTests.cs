using System;
using System.Numerics;
using Fulcrum.Collision;
using NUnit.Framework;

namespace Fulcrum.Tests.Collision
{
    public class DebugDrawTests
    {
        [Test]
        public void Debug_draw_lists_outlines_bounds_tree_nodes_and_contacts_on_request()
        {
            var s = WorldSettings.Default;
            s.Gravity = Vector3.Zero;
            var w = new World(s);
            w.AddShape(w.CreateBody(BodyDef.Static(new Vector3(0, -0.5f, 0))), ShapeDef.Of(ShapeGeometry.Box(new Vector3(5, 0.5f, 5))));
            BodyHandle box = w.CreateBody(BodyDef.Dynamic(new Vector3(0, 0.495f, 0)));
            w.AddShape(box, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            w.Step(1 / 60f);

            var buffer = new DebugDrawBuffer();
            w.DebugDraw(buffer, DebugDrawFlags.Shapes);
            Assert.That(buffer.Lines.Length, Is.EqualTo(24), "two boxes, 12 edges each");
            Assert.That(buffer.Points.Length, Is.EqualTo(0));

            buffer.Clear();
            w.DebugDraw(buffer, DebugDrawFlags.TreeNodes);
            Assert.That(buffer.Lines.Length, Is.EqualTo(24), "one leaf in each tree");

            buffer.Clear();
            w.DebugDraw(buffer, DebugDrawFlags.Contacts);
            Assert.That(buffer.Points.Length, Is.EqualTo(4));
            foreach (DebugPoint p in buffer.Points)
            {
                Assert.That(p.Position.Y, Is.EqualTo(-0.0025f).Within(1e-5f));
                Assert.That(p.Color, Is.EqualTo(DebugColor.Penetrating));
            }
            // Per point: a normal line of 0.1 m and a depth line as long as the overlap.
            Assert.That(buffer.Lines.Length, Is.EqualTo(8));
            Assert.That(Vector3.Distance(buffer.Lines[0].A, buffer.Lines[0].B), Is.EqualTo(0.1f).Within(1e-6f));
            Assert.That(Vector3.Distance(buffer.Lines[1].A, buffer.Lines[1].B), Is.EqualTo(0.005f).Within(1e-5f));

            buffer.Clear();
            w.DebugDraw(buffer, DebugDrawFlags.All);
            int total = buffer.Lines.Length;
            long allocated = 0;
            for (int round = 0; round < 2; round++)
            {
                buffer.Clear();
                long before = GC.GetAllocatedBytesForCurrentThread();
                w.DebugDraw(buffer, DebugDrawFlags.All);
                allocated = GC.GetAllocatedBytesForCurrentThread() - before;
            }
            Assert.That(allocated, Is.EqualTo(0), "a reused buffer does not grow again");
            Assert.That(buffer.Lines.Length, Is.EqualTo(total));
        }
    }
}
