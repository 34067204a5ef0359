using System;
using System.Numerics;
using Fulcrum.Components;
using NUnit.Framework;
using MeshCollider = Fulcrum.Components.MeshCollider;

namespace Fulcrum.Tests.Components
{
    public class MeshColliderTests
    {
        static Mesh Cube(float h)
        {
            var v = new Vector3[8];
            for (int i = 0; i < 8; i++) v[i] = new Vector3((i & 1) != 0 ? h : -h, (i & 2) != 0 ? h : -h, (i & 4) != 0 ? h : -h);
            return new Mesh(v, Array.Empty<int>()) { name = "cube" };
        }

        [Test]
        public void A_convex_mesh_collider_of_a_cube_gives_the_box_inertia()
        {
            var scene = new PhysicsScene();
            Entity e = scene.CreateEntity("Crate");
            var rb = e.AddComponent<Rigidbody>();
            rb.mass = 6f;
            var mc = e.AddComponent<MeshCollider>();
            mc.convex = true;
            mc.sharedMesh = Cube(0.5f);
            // A 1 m cube of 6 kg: I = m (a^2 + a^2) / 12 = 1 kg m^2 about each axis.
            Assert.That(rb.inertiaTensor.C0.X, Is.EqualTo(1f).Within(1e-4f));
            Assert.That(rb.inertiaTensor.C2.Z, Is.EqualTo(1f).Within(1e-4f));
            Assert.That(scene.world.GetShapeGeometry(mc.shape).Type, Is.EqualTo(ShapeType.ConvexHull));
        }

        [Test]
        public void A_static_triangle_mesh_ground_reports_the_landing_of_a_box()
        {
            var scene = new PhysicsScene(WorldSettings.Default, 1f / 60f);
            Entity ground = scene.CreateEntity("Terrain");
            var mc = ground.AddComponent<MeshCollider>();
            // Two triangles facing +y: (b - a) x (c - a) points up.
            mc.sharedMesh = new Mesh(
                new[] { new Vector3(-5, 0, -5), new Vector3(5, 0, -5), new Vector3(5, 0, 5), new Vector3(-5, 0, 5) },
                new[] { 0, 2, 1, 0, 3, 2 });
            Assert.That(scene.world.GetShapeGeometry(mc.shape).Type, Is.EqualTo(ShapeType.TriangleMesh));
            Entity crate = scene.CreateEntity("Crate", new Vector3(0, 1, 0));
            crate.AddComponent<Rigidbody>();
            crate.AddComponent<BoxCollider>();
            var log = crate.AddComponent<Recorder>();
            for (int k = 0; k < 60 && !log.Log.Contains("OnCollisionEnter"); k++) scene.Tick(1f / 60f);
            Assert.That(log.Log, Does.Contain("OnCollisionEnter"));
        }

        [Test]
        public void A_flat_point_cloud_cannot_make_a_hull_and_the_error_names_collider_and_mesh()
        {
            var scene = new PhysicsScene();
            Entity e = scene.CreateEntity("Sheet");
            e.AddComponent<Rigidbody>();
            var mc = e.AddComponent<MeshCollider>();
            mc.convex = true;
            var flat = new Mesh(new[] { Vector3.Zero, Vector3.UnitX, Vector3.UnitZ, new Vector3(1, 0, 1) }, Array.Empty<int>()) { name = "flat" };
            var ex = Assert.Throws<ArgumentException>(() => mc.sharedMesh = flat)!;
            Assert.That(ex.Message, Does.Contain("MeshCollider on 'Sheet': sharedMesh 'flat' cannot make a convex hull"));
            Assert.That(mc.sharedMesh, Is.Null);
        }
    }
}
