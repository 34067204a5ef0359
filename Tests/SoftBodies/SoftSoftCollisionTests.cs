using System;
using System.Numerics;
using Fulcrum.SoftBodies;
using Fulcrum.Tests.Foundation;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftBodies
{
    public class SoftSoftCollisionTests
    {
        static readonly NeoHookeanMaterial Jelly = new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e5f, 0.4f, 1000f);

        static float MinY(SoftBody body)
        {
            float min = float.MaxValue;
            foreach (Vector3 p in body.Positions) min = MathF.Min(min, p.Y);
            return min;
        }

        static float MaxY(SoftBody body)
        {
            float max = float.MinValue;
            foreach (Vector3 p in body.Positions) max = MathF.Max(max, p.Y);
            return max;
        }

        /// <summary>
        /// The smallest vertical gap between the facing surfaces of an upper and a lower body: each
        /// vertex of one measured to the other's surface triangles facing it (up-facing under the
        /// upper body's vertices, down-facing above the lower body's) whose horizontal projection
        /// holds it. Negative where the surfaces cross.
        /// </summary>
        internal static float MinGap(SoftBody upper, SoftBody lower) =>
            MathF.Min(Gap(upper, lower, 1f), Gap(lower, upper, -1f));

        static float Gap(SoftBody vertices, SoftBody surface, float up)
        {
            ReadOnlySpan<Vector3> p = vertices.Positions, x = surface.Positions;
            ReadOnlySpan<int> tris = surface.Mesh.SurfaceTriangles;
            float min = float.MaxValue;
            for (int t = 0; t < tris.Length; t += 3)
            {
                Vector3 a = x[tris[t]], b = x[tris[t + 1]], c = x[tris[t + 2]];
                Vector3 n = Vector3.Normalize(Vector3.Cross(b - a, c - a));
                if (n.Y * up < 0.5f) continue;
                float det = (b.X - a.X) * (c.Z - a.Z) - (c.X - a.X) * (b.Z - a.Z);
                foreach (Vector3 q in p)
                {
                    float u = ((q.X - a.X) * (c.Z - a.Z) - (c.X - a.X) * (q.Z - a.Z)) / det;
                    float v = ((b.X - a.X) * (q.Z - a.Z) - (q.X - a.X) * (b.Z - a.Z)) / det;
                    if (u < 0 || v < 0 || u + v > 1) continue;
                    float h = a.Y + u * (b.Y - a.Y) + v * (c.Y - a.Y);
                    float gap = (q.Y - h) * up;
                    if (gap > -0.1f) min = MathF.Min(min, gap);
                }
            }
            return min;
        }

        /// <summary>Drops a cube on a cube resting on the ground; returns the smallest gap between them over the run and at the end.</summary>
        static (float minGap, float endGap, float topCentre) Stack(bool collide)
        {
            World world = SoftBodyScenes.WorldWithGround();
            var lowerDef = SoftBodyScenes.Cube(0.3f, 3, Jelly, new Vector3(0, 0.155f, 0));
            var upperDef = SoftBodyScenes.Cube(0.3f, 3, Jelly, new Vector3(0.03f, 0.5f, -0.02f));
            upperDef.LinearVelocity = new Vector3(0, -1f, 0);
            upperDef.CollideWithSoftBodies = collide;
            SoftBody lower = world.GetSoftBody(world.CreateSoftBody(lowerDef));
            SoftBody upper = world.GetSoftBody(world.CreateSoftBody(upperDef));
            float minGap = float.MaxValue;
            for (int i = 0; i < 120; i++)
            {
                world.Step(SoftBodyScenes.Dt);
                minGap = MathF.Min(minGap, MinGap(upper, lower));
            }
            return (minGap, MinGap(upper, lower), upper.ComputeStats().Centroid.Y);
        }

        [Test]
        public void A_jelly_cube_dropped_on_another_comes_to_rest_on_top_without_interpenetrating()
        {
            var stack = Stack(collide: true);
            TestContext.Out.WriteLine($"min gap over the run {stack.minGap:F5} m, at rest {stack.endGap:F5} m, upper centroid {stack.topCentre:F4} m");
            Assert.That(stack.minGap, Is.GreaterThan(0.009f), "the surfaces never come closer than the two collision radii, less 1 mm");
            Assert.That(stack.endGap, Is.EqualTo(0.01f).Within(0.001f), "at rest the surfaces keep the two collision radii apart");
            Assert.That(stack.topCentre, Is.InRange(0.4f, 0.47f), "on top of the lower cube (0.3 m tall, squashed a little)");
        }

        [Test]
        public void With_soft_collision_off_the_cubes_pass_through_each_other()
        {
            var stack = Stack(collide: false);
            TestContext.Out.WriteLine($"min gap {stack.minGap:F4} m");
            Assert.That(stack.minGap, Is.LessThan(-0.05f), "the measure sees a crossing when there is one");
        }

        [Test]
        public void Free_collision_of_two_jellies_conserves_momentum_and_pushes_the_struck_one()
        {
            World world = SoftBodyScenes.ZeroGravityWorld();
            var a = SoftBodyScenes.Cube(0.3f, 3, Jelly, new Vector3(-0.4f, 0.08f, 0));
            a.LinearVelocity = new Vector3(2f, 0, 0.3f);
            a.Friction = 0.6f;
            var heavy = new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 2e5f, 0.4f, 2500f);
            var b = SoftBodyScenes.Cube(0.2f, 3, heavy, new Vector3(0, 0, 0));
            b.LinearVelocity = new Vector3(-0.5f, 0, 0);
            SoftBody bodyA = world.GetSoftBody(world.CreateSoftBody(a));
            SoftBody bodyB = world.GetSoftBody(world.CreateSoftBody(b));
            Vector3 before = bodyA.ComputeStats().Momentum + bodyB.ComputeStats().Momentum;
            Vector3 beforeB = bodyB.ComputeStats().Momentum;
            SoftBodyScenes.Run(world, 40);
            Vector3 after = bodyA.ComputeStats().Momentum + bodyB.ComputeStats().Momentum;
            Vector3 afterB = bodyB.ComputeStats().Momentum;
            float pA = (a.LinearVelocity * bodyA.TotalMass).Length();
            TestContext.Out.WriteLine($"total momentum before {before} after {after}; struck body {beforeB} -> {afterB}; A's momentum {pA:F3}");
            Assert.That(afterB.X - beforeB.X, Is.GreaterThan(0.3f * pA), "the struck body was pushed");
            Assert.That((after - before).Length(), Is.LessThan(0.01f * pA), "momentum within 1 % of the striker's");
        }

        [Test]
        public void Bodies_on_layers_that_exclude_each_other_do_not_collide()
        {
            World world = SoftBodyScenes.ZeroGravityWorld();
            var a = SoftBodyScenes.Cube(0.3f, 2, Jelly, new Vector3(-0.4f, 0, 0));
            a.LinearVelocity = new Vector3(2f, 0, 0);
            a.Layer = 1;
            var b = SoftBodyScenes.Cube(0.3f, 2, Jelly, new Vector3(0.4f, 0, 0));
            b.CollidesWith = ~(1u << 1);
            SoftBody bodyA = world.GetSoftBody(world.CreateSoftBody(a));
            SoftBody bodyB = world.GetSoftBody(world.CreateSoftBody(b));
            SoftBodyScenes.Run(world, 30);
            Assert.That(bodyB.ComputeStats().Momentum.Length(), Is.EqualTo(0f).Within(1e-4f));
            Assert.That(bodyA.ComputeStats().Centroid.X, Is.EqualTo(0.6f).Within(0.01f), "A went straight through");
        }

        [Test]
        public void A_stack_of_jellies_on_a_mesh_floor_and_a_hull_allocates_nothing_per_step()
        {
            World world = SoftBodyScenes.WorldWithGround();
            BodyHandle hull = world.CreateBody(BodyDef.Dynamic(new Vector3(0.6f, 0.2f, 0)));
            world.AddShape(hull, ShapeDef.Of(ShapeGeometry.ConvexHull(new[]
            {
                new Vector3(-0.1f, -0.1f, -0.1f), new Vector3(0.1f, -0.1f, -0.1f), new Vector3(0, 0.1f, -0.1f),
                new Vector3(-0.1f, -0.1f, 0.1f), new Vector3(0.1f, -0.1f, 0.1f), new Vector3(0, 0.1f, 0.1f),
            })));
            var floor = TriangleMesh.Create(
                new[] { new Vector3(-2, 0.001f, -2), new Vector3(-2, 0.001f, 2), new Vector3(2, 0.001f, 2), new Vector3(2, 0.001f, -2) },
                new[] { 0, 1, 2, 0, 2, 3 });
            BodyHandle ground = world.CreateBody(BodyDef.Static(Vector3.Zero));
            world.AddShape(ground, ShapeDef.Of(ShapeGeometry.TriangleMesh(floor)));
            world.CreateSoftBody(SoftBodyScenes.Cube(0.3f, 3, Jelly, new Vector3(0, 0.16f, 0)));
            world.CreateSoftBody(SoftBodyScenes.Cube(0.3f, 3, Jelly, new Vector3(0.05f, 0.48f, 0)));
            AllocationTests.AllocatedOverSteps(world, 60);
            Assert.That(AllocationTests.AllocatedOverSteps(world, 60), Is.EqualTo(0), "bytes allocated over 60 warm steps");
        }
    }
}
