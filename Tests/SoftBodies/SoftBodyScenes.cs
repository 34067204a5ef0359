using System;
using System.Numerics;
using Fulcrum;
using Fulcrum.SoftBodies;

namespace Fulcrum.Tests.SoftBodies
{
    /// <summary>Small scene builders shared by the soft-body tests.</summary>
    internal static class SoftBodyScenes
    {
        public const float Dt = 1f / 60f;

        public static World WorldWithGround(float groundY = 0f, float friction = 0.5f)
        {
            var world = new World();
            BodyHandle ground = world.CreateBody(BodyDef.Static(new Vector3(0, groundY, 0)));
            world.AddShape(ground, ShapeDef.Of(ShapeGeometry.Plane(Vector3.UnitY, 0f)).With((ref ShapeDef s) => s.Friction = friction));
            return world;
        }

        public static World ZeroGravityWorld()
        {
            var world = new World();
            world.Gravity = Vector3.Zero;
            return world;
        }

        public static SoftBodyDef Cube(float size, int cells, in NeoHookeanMaterial material, Vector3 position)
        {
            SoftBodyDef def = SoftBodyDef.Of(SoftMesh.Box(new Vector3(size), cells, cells, cells), material, position);
            return def;
        }

        public static void Run(World world, int steps)
        {
            for (int i = 0; i < steps; i++) world.Step(Dt);
        }

        public static float MaxDisplacement(ReadOnlySpan<Vector3> a, Vector3[] b)
        {
            float max = 0;
            for (int i = 0; i < a.Length; i++) max = MathF.Max(max, (a[i] - b[i]).Length());
            return max;
        }

        public static bool AllFinite(ReadOnlySpan<Vector3> v)
        {
            foreach (Vector3 p in v)
                if (!float.IsFinite(p.X) || !float.IsFinite(p.Y) || !float.IsFinite(p.Z)) return false;
            return true;
        }
    }
}
