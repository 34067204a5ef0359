using System.Numerics;
using Fulcrum;
using NUnit.Framework;

namespace Fulcrum.Tests.Foundation
{
    public class FreeFallTests
    {
        [Test]
        public void Free_fall_matches_the_exact_semi_implicit_euler_sequence_bit_for_bit()
        {
            var world = new World();
            BodyHandle ball = world.CreateBody(BodyDef.Dynamic(new Vector3(0, 10, 0)));
            world.AddShape(ball, ShapeDef.Of(ShapeGeometry.Sphere(0.5f)));
            const float dt = 1f / 60f;
            Vector3 g = world.Gravity, x = new Vector3(0, 10, 0), v = Vector3.Zero;
            for (int n = 0; n < 120; n++)
            {
                world.Step(dt);
                v += dt * (g * 1f + Vector3.Zero * 1f);
                x += v * dt;
                Assert.That(world.GetBody(ball).LinearVelocity, Is.EqualTo(v), $"step {n}");
                Assert.That(world.GetBody(ball).Position, Is.EqualTo(x), $"step {n}");
            }
        }
    }
}
