using System;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// Makes the <see cref="ShapeGeometry"/> of one scene shape (not a compound: the builder
    /// adds a compound's children one by one).
    /// </summary>
    public static class SceneGeometry
    {
        /// <summary>
        /// The geometry of <paramref name="shape"/>; <paramref name="path"/> names it in errors:
        /// a degenerate hull or mesh throws a <see cref="SceneException"/> at that path.
        /// </summary>
        public static ShapeGeometry Create(SceneShape shape, string path)
        {
            switch (shape)
            {
                case SceneSphere s: return ShapeGeometry.Sphere(s.Radius);
                case SceneBox b: return ShapeGeometry.Box(b.HalfExtents);
                case SceneCapsule c: return ShapeGeometry.Capsule(c.Radius, c.HalfHeight);
                case ScenePlane p: return ShapeGeometry.Plane(p.Normal, p.Offset);
                case SceneConvex h:
                    return Checked(path, () => ShapeGeometry.ConvexHull(h.Points.ToArray()));
                case SceneMesh m:
                    return Checked(path, () => ShapeGeometry.TriangleMesh(TriangleMesh.Create(m.Vertices.ToArray(), m.Triangles.ToArray())));
                default:
                    throw new ArgumentException($"{path}: a {SceneNames.Of(shape.Type)} has no single geometry; add its children one by one.", nameof(shape));
            }
        }

        // Hull and mesh checks (fewer than 4 non-coplanar points, degenerate triangles) happen
        // in their factories; report them at the shape's JSON path.
        static ShapeGeometry Checked(string path, Func<ShapeGeometry> build)
        {
            try
            {
                return build();
            }
            catch (ArgumentException e)
            {
                throw new SceneException(new SceneError(path, e.Message));
            }
        }
    }
}
