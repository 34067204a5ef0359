using System.Collections.Generic;
using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// The bodies, their shapes and meshes, and the materials they name.
    /// </summary>
    internal sealed partial class SceneChecker
    {
        void Materials()
        {
            var seen = new HashSet<string>();
            foreach (SceneMaterial m in _doc.Materials)
            {
                string path = JsonPath.Member("$.materials", m.Name ?? "");
                if (string.IsNullOrEmpty(m.Name)) Error(path, "a material needs a non-empty name");
                else if (!seen.Add(m.Name)) Error(path, $"duplicate material name '{m.Name}'");
                NonNegative(m.Friction, P(path, "friction"));
                InRange(m.Restitution, 0, 1, P(path, "restitution"));
                if (m.Density is float density) Positive(density, P(path, "density"));
            }
        }

        void Body(SceneBody b, string path)
        {
            if (b == null) { Error(path, "must not be null"); return; }
            if (string.IsNullOrEmpty(b.Name)) Error(P(path, "name"), "must be a non-empty name");
            if (b.Type != BodyType.Static && b.Type != BodyType.Kinematic && b.Type != BodyType.Dynamic)
                Error(P(path, "type"), "must be static, kinematic or dynamic");
            if (b.Shape == null) Error(P(path, "shape"), "missing required field");
            else Shape(b.Shape, P(path, "shape"), b.Type == BodyType.Static, child: false);
            MassAndMaterial(b.Mass, b.Material, b.Type, path);
            if (b.Density is float density && Positive(density, P(path, "density")) && b.Mass != null)
                Error(P(path, "density"), "mass and density are both given: give one");
            Coordinate(b.Position, P(path, "position"));
            Rotation(b.Rotation, P(path, "rotation"));
            Speed(b.Velocity, P(path, "velocity"));
            Speed(b.AngularVelocity, P(path, "angularVelocity"));
            if (b.Type == BodyType.Static)
            {
                if (b.Velocity != Vector3.Zero) Error(P(path, "velocity"), "a static body cannot move: must be [0, 0, 0]");
                if (b.AngularVelocity != Vector3.Zero) Error(P(path, "angularVelocity"), "a static body cannot move: must be [0, 0, 0]");
                if (b.Ccd) Error(P(path, "ccd"), "a static body cannot use continuous collision");
            }
            if ((b.LockAxes & ~AxisLocks.All) != 0)
                Error(P(path, "lockAxes"), $"unknown axis bits 0x{(int)b.LockAxes:X} (AxisLocks has linearX/Y/Z and angularX/Y/Z)");
            else if (b.LockAxes != AxisLocks.None && b.Type != BodyType.Dynamic)
                Error(P(path, "lockAxes"), $"a {SceneNames.Of(b.Type)} body is not moved by the solver: axis locks are for dynamic bodies");
        }

        void MassAndMaterial(float? mass, string? material, BodyType type, string path)
        {
            if (material != null)
            {
                if (_doc.FindMaterial(material) == null) Error(P(path, "material"), $"no material named '{material}' in $.materials");
            }
            if (mass is float kg)
            {
                if (type != BodyType.Dynamic) Error(P(path, "mass"), $"a {SceneNames.Of(type)} body has no mass: remove it or make the body dynamic");
                else if (Positive(kg, P(path, "mass"))) Upto(kg, Limits.MinMass, Limits.MaxMass, P(path, "mass"), "Limits.MinMass/MaxMass");
            }
        }

        void Shape(SceneShape s, string path, bool isStatic, bool child)
        {
            switch (s)
            {
                case SceneSphere sphere:
                    Size(sphere.Radius, P(path, "radius"));
                    break;
                case SceneBox box:
                    Size(box.HalfExtents, P(path, "halfExtents"));
                    break;
                case SceneCapsule capsule:
                    Size(capsule.Radius, P(path, "radius"));
                    if (NonNegative(capsule.HalfHeight, P(path, "halfHeight"))) Upto(capsule.HalfHeight, 0, Limits.MaxShapeSize, P(path, "halfHeight"), "Limits.MaxShapeSize");
                    break;
                case SceneConvex convex:
                    if (convex.Points.Count < 4) Error(P(path, "points"), $"a convex hull needs at least 4 points, got {convex.Points.Count}");
                    if (convex.Points.Count > Limits.MaxHullPoints)
                        Error(P(path, "points"), $"at most {Limits.MaxHullPoints} points (Limits.MaxHullPoints), got {convex.Points.Count}");
                    else
                        for (int i = 0; i < convex.Points.Count; i++) Extent(convex.Points[i], JsonPath.Index(P(path, "points"), i));
                    break;
                case ScenePlane plane:
                    if (child) Error(P(path, "type"), "a plane cannot be a compound child");
                    else if (!isStatic) Error(P(path, "type"), "a plane can only be the shape of a static body");
                    if (Finite(plane.Normal, P(path, "normal")) && !(plane.Normal.Length() > 1e-6f)) Error(P(path, "normal"), "must be non-zero");
                    if (Finite(plane.Offset, P(path, "offset"))) Upto(plane.Offset, -Limits.MaxPosition, Limits.MaxPosition, P(path, "offset"), "Limits.MaxPosition");
                    break;
                case SceneMesh mesh:
                    if (child) Error(P(path, "type"), "a mesh cannot be a compound child");
                    else if (!isStatic) Error(P(path, "type"), "a mesh can only be the shape of a static body");
                    Mesh(mesh, path);
                    break;
                case SceneCompound compound:
                    if (child) { Error(P(path, "type"), "compounds cannot be nested"); break; }
                    string children = P(path, "children");
                    if (compound.Children.Count == 0) Error(children, "a compound needs at least one child");
                    for (int i = 0; i < compound.Children.Count; i++)
                    {
                        SceneCompoundChild c = compound.Children[i];
                        string cp = JsonPath.Index(children, i);
                        if (c.Shape == null) Error(P(cp, "shape"), "missing required field");
                        else Shape(c.Shape, P(cp, "shape"), isStatic, child: true);
                        Extent(c.Position, P(cp, "position"));
                        Rotation(c.Rotation, P(cp, "rotation"));
                    }
                    break;
            }
        }

        void Mesh(SceneMesh mesh, string path)
        {
            string vertices = P(path, "vertices"), triangles = P(path, "triangles");
            if (mesh.Vertices.Count < 3) Error(vertices, $"a mesh needs at least 3 vertices, got {mesh.Vertices.Count}");
            for (int i = 0; i < mesh.Vertices.Count; i++) Coordinate(mesh.Vertices[i], JsonPath.Index(vertices, i));
            if (mesh.Triangles.Count == 0 || mesh.Triangles.Count % 3 != 0)
                Error(triangles, $"needs at least one triangle of 3 indices, got {mesh.Triangles.Count} indices");
            for (int i = 0; i < mesh.Triangles.Count; i++)
            {
                int index = mesh.Triangles[i];
                if (index < 0 || index >= mesh.Vertices.Count)
                    Error(JsonPath.Index(JsonPath.Index(triangles, i / 3), i % 3), $"vertex index {index} is out of range 0..{mesh.Vertices.Count - 1}");
            }
        }
    }
}
