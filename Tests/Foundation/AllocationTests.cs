using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using NUnit.Framework;

namespace Fulcrum.Tests.Foundation
{
    public class AllocationTests
    {
        // MethodImplOptions.AggressiveOptimization by value: .NET Standard 2.1 (what Unity
        // compiles against) lacks the name; .NET honours the bit and Mono ignores it.
        const MethodImplOptions AggressiveOptimization = (MethodImplOptions)512;

        // Fully optimised from the first call: a tier-0 loop would be patched by on-stack
        // replacement mid-measurement, and that transition itself allocates a few bytes.
        [MethodImpl(AggressiveOptimization | MethodImplOptions.NoInlining)]
        public static long AllocatedOverSteps(World world, int steps, float dt = 1f / 60f)
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int n = 0; n < steps; n++) world.Step(dt);
            return GC.GetAllocatedBytesForCurrentThread() - before;
        }

        [Test]
        public void A_warm_world_allocates_nothing_per_step()
        {
            var world = new World();
            BodyHandle ground = world.CreateBody(BodyDef.Static(Vector3.Zero));
            world.AddShape(ground, ShapeDef.Of(ShapeGeometry.Box(new Vector3(50, 0.5f, 50))));
            for (int i = 0; i < 10; i++)
            {
                BodyHandle box = world.CreateBody(BodyDef.Dynamic(new Vector3(0, 1 + 1.01f * i, 0)));
                world.AddShape(box, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            }
            for (int i = 0; i < 50; i++)
            {
                BodyDef def = BodyDef.Dynamic(new Vector3(5 + (i % 7) * 1.1f, 1 + i / 7 * 1.1f, 5));
                def.AngularVelocity = new Vector3(0.1f * i, 0.2f, -0.05f * i);
                BodyHandle b = world.CreateBody(def);
                ShapeGeometry g = (i % 3) switch
                {
                    0 => ShapeGeometry.Sphere(0.5f),
                    1 => ShapeGeometry.Capsule(0.3f, 0.4f),
                    _ => ShapeGeometry.Box(new Vector3(0.3f, 0.4f, 0.5f)),
                };
                world.AddShape(b, ShapeDef.Of(g));
            }
            // Warm up past the settling phase: contact and solver buffers grow (by doubling) each
            // time the contact count reaches a new high, which is amortised, not per-step garbage.
            AllocatedOverSteps(world, 300);
            Assert.That(AllocatedOverSteps(world, 1000), Is.EqualTo(0), "bytes allocated over 1,000 warm steps");
        }
    }
}
