using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;

namespace Fulcrum.Tests.Collision
{
    /// <summary>Shared helpers: run a pair function, build poses, random numbers.</summary>
    internal static class CollisionTestKit
    {
        public static ContactBuffer Collide(ShapeGeometry a, Pose pa, ShapeGeometry b, Pose pb, float speculative = 0.02f)
        {
            var buffer = new ContactBuffer();
            buffer.Clear(speculative);
            CollisionTable.Collide(a, pa, b, pb, buffer);
            buffer.Reduce();
            return buffer;
        }

        public static Pose At(float x, float y, float z) => new Pose(new Vector3(x, y, z), Quaternion.Identity);

        public static Pose At(Vector3 p, Quaternion q) => new Pose(p, q);

        public static Quaternion AboutY(float degrees) => Quaternion.CreateFromAxisAngle(Vector3.UnitY, degrees * MathF.PI / 180f);

        public static Quaternion AboutX(float degrees) => Quaternion.CreateFromAxisAngle(Vector3.UnitX, degrees * MathF.PI / 180f);

        public static Quaternion AboutZ(float degrees) => Quaternion.CreateFromAxisAngle(Vector3.UnitZ, degrees * MathF.PI / 180f);

        public static float MinSeparation(ContactBuffer b) => b.MinSeparation();

        public static Quaternion RandomRotation(Random r)
        {
            var q = new Quaternion((float)(r.NextDouble() * 2 - 1), (float)(r.NextDouble() * 2 - 1), (float)(r.NextDouble() * 2 - 1), (float)(r.NextDouble() * 2 - 1));
            return q.Length() < 1e-3f ? Quaternion.Identity : Quaternion.Normalize(q);
        }

        public static Vector3 RandomVector(Random r, float scale) =>
            new Vector3((float)(r.NextDouble() * 2 - 1), (float)(r.NextDouble() * 2 - 1), (float)(r.NextDouble() * 2 - 1)) * scale;
    }
}
