using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Tree callback of the world's shape casts: sweeps the cast shape against each shape
    /// whose fat box overlaps the swept bounds (planes exactly, convex shapes and mesh
    /// triangles by conservative advancement). Keeps the closest hit, or the nearest
    /// <see cref="Capacity"/> hits sorted by distance then shape slot.
    /// </summary>
    internal struct ShapeCastQuery : ITreeOverlapCallback
    {
        public World World;
        public QueryFilter Filter;
        public SupportShape Cast;
        public Vector3 Direction;   // unit
        public float Length;
        public Aabb SweptBounds;
        public bool All;
        public ShapeCastHit Best;
        public bool HasHit;
        public ShapeCastHit[] Hits;
        public int Capacity;
        public int Found;

        public bool Visit(int proxyId, int shape)
        {
            if (!World.PassesFilter(shape, Filter)) return true;
            ShapeStorage s = World.Shapes;
            ShapeGeometry g = s.Geometry[shape];
            Pose pose = World.ShapeWorldPose(shape);
            Vector3 motion = Direction * Length;
            float fraction;
            Vector3 normal, point;
            bool hit;
            switch (g.Type)
            {
                case ShapeType.Plane:
                {
                    Vector3 n = pose.TransformDirection(g.Normal);
                    float offset = Vector3.Dot(n, pose.TransformPoint(g.Normal * g.Offset));
                    hit = ShapeCaster.CastPlane(Cast, motion, n, offset, 0, out fraction, out point);
                    normal = n;
                    break;
                }
                case ShapeType.TriangleMesh:
                    hit = CastMesh((TriangleMesh)g.Data!, pose, motion, out fraction, out normal, out point);
                    break;
                default:
                    hit = ShapeCaster.Cast(Cast, motion, SupportShape.From(g, pose), 0, out fraction, out normal, out point);
                    break;
            }
            if (!hit) return true;
            var h = new ShapeCastHit
            {
                Shape = new ShapeHandle(shape, s.Generation[shape], World.Id),
                Body = World.BodyHandleOf(s.Body[shape]),
                Point = point,
                Normal = normal,
                Distance = fraction * Length,
            };
            if (!All)
            {
                if (!HasHit || NearestHits.Before(h, Best)) Best = h;
                HasHit = true;
                return true;
            }
            NearestHits.Insert(Hits, Capacity, ref Found, h);
            return true;
        }

        struct TriangleSweep : ITreeOverlapCallback
        {
            public TriangleMesh Mesh;
            public SupportShape Cast;       // mesh frame
            public Vector3 Motion;          // mesh frame
            public float Best;
            public Vector3 Normal, Point;

            public bool Visit(int proxyId, int triangle)
            {
                Mesh.GetTriangle(triangle, out Vector3 a, out Vector3 b, out Vector3 c);
                // One-sided: only a motion into the front face can hit it.
                if (Vector3.Dot(Mesh.Normals[triangle], Motion) >= 0) return true;
                if (ShapeCaster.Cast(Cast, Motion, SupportShape.Triangle(a, b, c), 0, out float f, out Vector3 n, out Vector3 p) && f < Best)
                {
                    Best = f;
                    Normal = n;
                    Point = p;
                }
                return true;
            }
        }

        bool CastMesh(TriangleMesh mesh, in Pose pose, Vector3 motion, out float fraction, out Vector3 normal, out Vector3 point)
        {
            Pose inverse = pose.Inverse();
            var sweep = new TriangleSweep { Mesh = mesh, Best = float.MaxValue, Motion = inverse.TransformDirection(motion) };
            sweep.Cast = Cast;
            Mat3 r = Mat3.FromQuaternion(inverse.Rotation);
            sweep.Cast.Center = inverse.TransformPoint(Cast.Center);
            sweep.Cast.A = inverse.TransformPoint(Cast.A);
            sweep.Cast.B = inverse.TransformPoint(Cast.B);
            sweep.Cast.C = inverse.TransformPoint(Cast.C);
            sweep.Cast.Axes = r * Cast.Axes;
            Aabb start = sweep.Cast.Bounds();
            Aabb box = Aabb.Union(start, new Aabb(start.Min + sweep.Motion, start.Max + sweep.Motion));
            mesh.Bvh.Query(box, ref sweep);
            fraction = sweep.Best;
            normal = pose.TransformDirection(sweep.Normal);
            point = pose.TransformPoint(sweep.Point);
            return sweep.Best <= 1;
        }
    }
}
