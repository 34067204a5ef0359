using System.Collections.Generic;
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

        public static BodyHandle Sphere(World w, Vector3 position, float radius, float mass, float friction = 0.6f, float restitution = 0f)
        {
            BodyDef d = BodyDef.Dynamic(position);
            d.Mass = mass;
            BodyHandle b = w.CreateBody(d);
            ShapeDef s = ShapeDef.Of(ShapeGeometry.Sphere(radius));
            s.Friction = friction;
            s.Restitution = restitution;
            w.AddShape(b, s);
            return b;
        }

        public static BodyHandle Box(World w, Vector3 position, Vector3 halfExtents, float mass, Quaternion? rotation = null, float friction = 0.6f)
        {
            BodyDef d = BodyDef.Dynamic(position);
            d.Mass = mass;
            if (rotation.HasValue) d.Rotation = rotation.Value;
            BodyHandle b = w.CreateBody(d);
            ShapeDef s = ShapeDef.Of(ShapeGeometry.Box(halfExtents));
            s.Friction = friction;
            w.AddShape(b, s);
            return b;
        }

        public static BodyHandle StaticBox(World w, Vector3 position, Vector3 halfExtents, Quaternion? rotation = null, float friction = 0.6f, float restitution = 0f)
        {
            BodyDef d = BodyDef.Static(position);
            if (rotation.HasValue) d.Rotation = rotation.Value;
            BodyHandle b = w.CreateBody(d);
            ShapeDef s = ShapeDef.Of(ShapeGeometry.Box(halfExtents));
            s.Friction = friction;
            s.Restitution = restitution;
            w.AddShape(b, s);
            return b;
        }

        /// <summary>The scene file's ground: a static 100 x 1 x 100 m box whose top is y = 0.</summary>
        public static BodyHandle Ground(World w, float friction = 0.6f, float restitution = 0f) =>
            StaticBox(w, new Vector3(0, -0.5f, 0), new Vector3(50, 0.5f, 50), null, friction, restitution);

        /// <summary>A column of 1 m, 1 kg cubes standing on y = 0, bottom first.</summary>
        public static BodyHandle[] Tower(World w, int count)
        {
            var boxes = new BodyHandle[count];
            for (int i = 0; i < count; i++) boxes[i] = Box(w, new Vector3(0, 0.5f + i, 0), new Vector3(0.5f), 1f);
            return boxes;
        }

        /// <summary>A one-box-deep pyramid of 1 m, 1 kg cubes with <paramref name="baseCount"/> at the base; the last body is the top.</summary>
        public static BodyHandle[] Pyramid(World w, int baseCount)
        {
            var list = new List<BodyHandle>();
            for (int row = 0; row < baseCount; row++)
                for (int i = 0; i < baseCount - row; i++)
                    list.Add(Box(w, new Vector3(-0.5f * (baseCount - row - 1) + i, 0.5f + row, 0), new Vector3(0.5f), 1f));
            return list.ToArray();
        }
    }
}
