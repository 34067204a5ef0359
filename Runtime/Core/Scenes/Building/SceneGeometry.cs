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
        /// The geometry of <paramref name="shape"/>; <paramref name="path"/> names it in errors.
        /// Convex hulls and triangle meshes throw <see cref="NotSupportedException"/> naming the
        /// path until Core has geometry factories for them.
        /// </summary>
        public static ShapeGeometry Create(SceneShape shape, string path)
        {
            switch (shape)
            {
                case SceneSphere s: return ShapeGeometry.Sphere(s.Radius);
                case SceneBox b: return ShapeGeometry.Box(b.HalfExtents);
                case SceneCapsule c: return ShapeGeometry.Capsule(c.Radius, c.HalfHeight);
                case ScenePlane p: return ShapeGeometry.Plane(p.Normal, p.Offset);
                // Seam for the collision branch: build these with its ShapeGeometry factories.
                case SceneConvex _:
                    throw new NotSupportedException($"{path}: convex shapes are read but cannot be built yet: Core has no convex hull geometry factory.");
                case SceneMesh _:
                    throw new NotSupportedException($"{path}: mesh shapes are read but cannot be built yet: Core has no triangle mesh geometry factory.");
                default:
                    throw new ArgumentException($"{path}: a {SceneNames.Of(shape.Type)} has no single geometry; add its children one by one.", nameof(shape));
            }
        }
    }
}
