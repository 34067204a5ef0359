using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Numerics;
using Fulcrum.SoftBodies;

namespace Fulcrum.Benchmarks
{
    /// <summary>
    /// Milliseconds per 60 Hz step of the soft-body stage (default substeps, stable Neo-Hookean
    /// jelly falling onto a ground plane) for tet meshes of ~1k, ~10k and ~50k elements and a
    /// 64 x 64 cloth over a sphere; and the bytes allocated per step (must be 0).
    /// </summary>
    public sealed class SoftBodyBenchmark : IBenchmark
    {
        public string Name => "softbody";

        public string Description => "ms/step and bytes/step of XPBD soft bodies: 1k/10k/50k tets, 64x64 cloth";

        public void Run(TextWriter output, bool quick)
        {
            int warm = quick ? 5 : 30, measured = quick ? 10 : 60;
            output.WriteLine($"{"scene",-28} {"elements",9} {"threads",7} {"substeps",8} {"median ms",10} {"p95 ms",8} {"bytes/step",10}");
            var scenes = new List<(string, Func<int, World>)>
            {
                ("box 6x6x5 (1k tets)", t => Jelly(t, 6, 6, 5)),
                ("box 12x12x12 (10k tets)", t => Jelly(t, 12, 12, 12)),
                ("cloth 64x64 over a ball", Cloth),
            };
            if (!quick) scenes.Add(("box 20x20x21 (50k tets)", t => Jelly(t, 20, 20, 21)));
            foreach (var (name, build) in scenes)
            {
                foreach (int threads in new[] { 1, Environment.ProcessorCount })
                {
                    if (threads == 1 && name.Contains("50k") && Environment.ProcessorCount > 1 && quick) continue;
                    World world = build(threads);
                    SoftBody body = SoftBodySystem.Of(world)![0];
                    const float dt = 1f / 60f;
                    for (int i = 0; i < warm; i++) world.Step(dt);
                    var times = new double[measured];
                    long bytes = GC.GetAllocatedBytesForCurrentThread();
                    bytes = GC.GetAllocatedBytesForCurrentThread();
                    for (int i = 0; i < measured; i++)
                    {
                        long t0 = Stopwatch.GetTimestamp();
                        world.Step(dt);
                        times[i] = (Stopwatch.GetTimestamp() - t0) * 1000.0 / Stopwatch.Frequency;
                    }
                    bytes = GC.GetAllocatedBytesForCurrentThread() - bytes;
                    Array.Sort(times);
                    output.WriteLine($"{name,-28} {body.ElementCount,9} {threads,7} {body.SubstepsFor(dt),8} {times[measured / 2],10:F3} {times[(int)(measured * 0.95)],8:F3} {bytes / measured,10}");
                    if (threads == Environment.ProcessorCount) break;
                }
            }
        }

        static World Ground(int threads)
        {
            WorldSettings settings = WorldSettings.Default;
            settings.Threads = threads;
            var world = new World(settings);
            BodyHandle ground = world.CreateBody(BodyDef.Static(Vector3.Zero));
            world.AddShape(ground, ShapeDef.Of(ShapeGeometry.Plane(Vector3.UnitY, 0)));
            return world;
        }

        static World Jelly(int threads, int nx, int ny, int nz)
        {
            World world = Ground(threads);
            SoftMesh mesh = SoftMesh.Box(new Vector3(0.1f * nx, 0.1f * ny, 0.1f * nz), nx, ny, nz);
            world.CreateSoftBody(SoftBodyDef.Of(mesh, MaterialPresets.Rubber, new Vector3(0, 0.05f * ny + 0.1f, 0)));
            return world;
        }

        static World Cloth(int threads)
        {
            World world = Ground(threads);
            BodyHandle ball = world.CreateBody(BodyDef.Static(new Vector3(0, 0.5f, 0)));
            world.AddShape(ball, ShapeDef.Of(ShapeGeometry.Sphere(0.4f)));
            world.CreateSoftBody(SoftBodyDef.Of(SoftMesh.Cloth(2f, 2f, 64, 64), MaterialPresets.Cloth, new Vector3(0, 1f, 0)));
            return world;
        }
    }
}
