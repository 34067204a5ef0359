using System;
using System.Numerics;
using Fulcrum;
using NUnit.Framework;
using static Fulcrum.Tests.Solver.SolverTestScenes;

namespace Fulcrum.Tests.Solver
{
    /// <summary>The SIMD contact path (net10) against the scalar one it mirrors.</summary>
    public partial class WideContactTests
    {
        const float Dt = 1f / 60f;

        static (Vector3[] positions, int groups) Pyramid(bool wide)
        {
            WorldSettings s = WorldSettings.Default;
            s.EnableSleeping = false;
            var w = new World(s);
            w.SolverContextForTests.WideContacts = wide;
            Ground(w);
            BodyHandle[] boxes = SolverTestScenes.Pyramid(w, 12);
            for (int n = 0; n < 90; n++) w.Step(Dt);
            var p = new Vector3[boxes.Length];
            for (int i = 0; i < boxes.Length; i++) p[i] = w.GetBody(boxes[i]).Position;
            return (p, w.SolverContextForTests.WideGroupCount);
        }

        static float BoxBounceApex(bool wide)
        {
            var w = new World();
            w.SolverContextForTests.WideContacts = wide;
            Ground(w, restitution: 0.5f);
            BodyDef d = BodyDef.Dynamic(new Vector3(0, 2.5f, 0));
            d.Mass = 1f;
            BodyHandle box = w.CreateBody(d);
            ShapeDef sd = ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f)));
            sd.Restitution = 0.5f;
            w.AddShape(box, sd);
            float apex = 0, prev = 0;
            bool up = false;
            for (int n = 0; n < 120 && apex == 0; n++)
            {
                w.Step(Dt);
                float vy = w.GetBody(box).LinearVelocity.Y;
                if (vy > 0) up = true;
                if (up && prev > 0 && vy <= 0) apex = w.GetBody(box).Position.Y - 0.5f;
                prev = vy;
            }
            return apex;
        }

        [Test]
        public void Wide_and_scalar_paths_bounce_a_box_to_the_same_height()
        {
            float scalar = BoxBounceApex(false), wide = BoxBounceApex(true);
            TestContext.Out.WriteLine($"apex scalar {scalar:F4} m, wide {wide:F4} m (e^2 h = 0.5 m)");
            Assert.That(scalar, Is.EqualTo(0.5f).Within(0.05f));
            Assert.That(wide, Is.EqualTo(scalar).Within(1e-3f));
        }
    }
}
