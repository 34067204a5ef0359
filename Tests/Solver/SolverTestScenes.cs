using System.Numerics;
using Fulcrum;

namespace Fulcrum.Tests.Solver
{
    /// <summary>Small builders shared by the solver tests.</summary>
    static class SolverTestScenes
    {
        public static WorldSettings Settings(SolverType solver)
        {
            WorldSettings s = WorldSettings.Default;
            s.Solver = solver;
            return s;
        }

        public static BodyHandle Sphere(World w, Vector3 position, float radius, float mass)
        {
            BodyDef d = BodyDef.Dynamic(position);
            d.Mass = mass;
            BodyHandle b = w.CreateBody(d);
            w.AddShape(b, ShapeDef.Of(ShapeGeometry.Sphere(radius)));
            return b;
        }

        public static BodyHandle Box(World w, Vector3 position, Vector3 halfExtents, float mass, Quaternion? rotation = null)
        {
            BodyDef d = BodyDef.Dynamic(position);
            d.Mass = mass;
            if (rotation.HasValue) d.Rotation = rotation.Value;
            BodyHandle b = w.CreateBody(d);
            w.AddShape(b, ShapeDef.Of(ShapeGeometry.Box(halfExtents)));
            return b;
        }

        public static BodyHandle StaticBox(World w, Vector3 position, Vector3 halfExtents, Quaternion? rotation = null)
        {
            BodyDef d = BodyDef.Static(position);
            if (rotation.HasValue) d.Rotation = rotation.Value;
            BodyHandle b = w.CreateBody(d);
            w.AddShape(b, ShapeDef.Of(ShapeGeometry.Box(halfExtents)));
            return b;
        }
    }
}
