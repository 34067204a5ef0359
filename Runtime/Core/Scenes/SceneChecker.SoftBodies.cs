using System.Collections.Generic;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// A soft body: its mesh (generated, TetGen or OBJ files), material, solver settings
    /// and pins.
    /// </summary>
    internal sealed partial class SceneChecker
    {
        void SoftBody(SceneSoftBody s, string path, HashSet<string> bodies, Dictionary<string, string> names)
        {
            if (s == null) { Error(path, "must not be null"); return; }
            if (string.IsNullOrEmpty(s.Name)) Error(P(path, "name"), "must be a non-empty name");
            else if (names.TryGetValue(s.Name, out string? at)) Error(P(path, "name"), $"duplicate soft body name '{s.Name}' (first used at {at})");
            else names.Add(s.Name, path);

            string mesh = P(path, "mesh");
            if (s.Mesh == null) Error(mesh, "missing required field");
            else SoftMesh(s.Mesh, mesh);
            SoftMaterial(s.Material, P(path, "material"));
            Coordinate(s.Position, P(path, "position"));
            Rotation(s.Rotation, P(path, "rotation"));
            Speed(s.Velocity, P(path, "velocity"));
            SoftSettings(s, path);
            for (int i = 0; i < s.Pinned.Count; i++)
            {
                ScenePin pin = s.Pinned[i];
                string pp = JsonPath.Index(P(path, "pinned"), i);
                if (Finite(pin.Min, P(pp, "min")) && Finite(pin.Max, P(pp, "max"))
                    && (pin.Max.X < pin.Min.X || pin.Max.Y < pin.Min.Y || pin.Max.Z < pin.Min.Z))
                    Error(P(pp, "max"), $"must be >= min on every axis, got min {V(pin.Min)} and max {V(pin.Max)}");
                if (pin.To != null && !Exists(pin.To, bodies)) Error(P(pp, "to"), $"no body named '{pin.To}'");
            }
            string f = P(path, "initialDeformation");
            if (!s.InitialDeformation.IsFinite) Error(f, "must be finite");
            else if (s.InitialDeformation.Determinant == 0) Error(f, "must be invertible (its determinant is 0)");
            for (int i = 0; i < s.Probes.Count; i++) Finite(s.Probes[i], JsonPath.Index(P(path, "probes"), i));
            if (s.Plasticity is ScenePlasticity pl)
            {
                string pp = P(path, "plasticity");
                if (s.Mesh != null && s.Mesh.IsShell) Error(pp, $"needs a volume mesh; a {SceneNames.Of(s.Mesh.Type)} mesh is a triangle shell");
                NonNegative(pl.YieldStrain, P(pp, "yieldStrain"));
                Positive(pl.FlowRate, P(pp, "flowRate"));
                Positive(pl.MaxStrain, P(pp, "maxStrain"));
            }
        }

        // The solver and contact settings; each is optional (null: the engine's default).
        void SoftSettings(SceneSoftBody s, string path)
        {
            if (s.Substeps is int substeps) IntInRange(substeps, 0, 1000, P(path, "substeps"));
            if (s.Iterations is int iterations) IntInRange(iterations, 1, 1000, P(path, "iterations"));
            if (s.DampingTime is float dampingTime) NonNegative(dampingTime, P(path, "dampingTime"));
            if (s.Solver == "newton" && s.Mesh?.Type == SceneSoftMeshType.Cloth)
                Error(P(path, "solver"), "newton solves tetrahedra; a cloth (shell) mesh needs xpbd");
            if (s.LinearDamping is float linearDamping) NonNegative(linearDamping, P(path, "linearDamping"));
            if (s.GravityScale is float gravityScale) Finite(gravityScale, P(path, "gravityScale"));
            if (s.Friction is float friction) NonNegative(friction, P(path, "friction"));
            if (s.CollisionRadius is float radius) NonNegative(radius, P(path, "collisionRadius"));
            if (s.Layer is int layer) IntInRange(layer, 0, 31, P(path, "layer"));
            if (s.CollidesWith is int[] layers)
                for (int i = 0; i < layers.Length; i++) IntInRange(layers[i], 0, 31, JsonPath.Index(P(path, "collidesWith"), i));
        }

        void SoftMesh(SceneSoftMesh m, string path)
        {
            string cells = P(path, "cells");
            switch (m)
            {
                case SceneSoftBox box:
                    Positive(box.Size, P(path, "size"));
                    if (box.Cells == null || box.Cells.Length != 3) Error(cells, "must be [nx, ny, nz]");
                    else
                    {
                        bool ok = true;
                        for (int a = 0; a < 3; a++) ok &= AtLeast(box.Cells[a], 1, JsonPath.Index(cells, a));
                        if (ok && (long)box.Cells[0] * box.Cells[1] * box.Cells[2] > SceneValidator.MaxBodies)
                            Error(cells, $"more than {SceneValidator.MaxBodies} cells");
                    }
                    break;
                case SceneSoftSphere sphere:
                    Positive(sphere.Radius, P(path, "radius"));
                    GridCells(sphere.Cells, SceneSoftSphere.MinCells, cells, 3);
                    break;
                case SceneSoftCapsule capsule:
                    Positive(capsule.Radius, P(path, "radius"));
                    NonNegative(capsule.HalfHeight, P(path, "halfHeight"));
                    GridCells(capsule.Cells, SceneSoftSphere.MinCells, cells, 3);
                    break;
                case SceneSoftBeam beam:
                    Positive(beam.Length, P(path, "length"));
                    Positive(beam.Thickness, P(path, "thickness"));
                    GridCells(beam.Cells, 1, cells, 1);
                    break;
                case SceneSoftCloth cloth:
                    Positive(cloth.Size.X, JsonPath.Index(P(path, "size"), 0));
                    Positive(cloth.Size.Y, JsonPath.Index(P(path, "size"), 1));
                    if (cloth.Cells == null || cloth.Cells.Length != 2) Error(cells, "must be [nx, nz]");
                    else
                    {
                        bool ok = GridCells(cloth.Cells[0], 1, JsonPath.Index(cells, 0), 1);
                        ok &= GridCells(cloth.Cells[1], 1, JsonPath.Index(cells, 1), 1);
                        if (ok && (long)cloth.Cells[0] * cloth.Cells[1] > SceneValidator.MaxBodies) Error(cells, $"more than {SceneValidator.MaxBodies} cells");
                    }
                    Positive(cloth.Thickness, P(path, "thickness"));
                    NonNegative(cloth.BendingScale, P(path, "bendingScale"));
                    break;
                case SceneSoftTetGen tetgen:
                    FilePath(tetgen.Node, P(path, "node"));
                    FilePath(tetgen.Ele, P(path, "ele"));
                    break;
                case SceneSoftSurface surface:
                    FilePath(surface.File, P(path, "file"));
                    if (surface.Resolution < SceneSoftSurface.MinResolution || surface.Resolution > SceneSoftSurface.MaxResolution)
                        Error(P(path, "resolution"), $"must be in [{SceneSoftSurface.MinResolution}, {SceneSoftSurface.MaxResolution}], got {surface.Resolution}");
                    break;
                case SceneSoftObj obj:
                    FilePath(obj.File, P(path, "file"));
                    Positive(obj.Thickness, P(path, "thickness"));
                    NonNegative(obj.BendingScale, P(path, "bendingScale"));
                    break;
            }
        }

        // Cells along one grid axis, in [min, MaxGridCells]; the grid (of the given dimension) stays within MaxBodies cells.
        bool GridCells(int n, int min, string path, int dimension)
        {
            if (n < min || n > SceneValidator.MaxGridCells) { Error(path, $"must be in [{min}, {SceneValidator.MaxGridCells}], got {n}"); return false; }
            long total = 1;
            for (int k = 0; k < dimension; k++) total *= n;
            if (total > SceneValidator.MaxBodies) { Error(path, $"more than {SceneValidator.MaxBodies} cells ({n}^{dimension})"); return false; }
            return true;
        }

        void FilePath(string file, string path)
        {
            if (string.IsNullOrWhiteSpace(file)) Error(path, "must be a non-empty file path");
        }

        void SoftMaterial(SceneSoftMaterial? m, string path)
        {
            if (m == null) { Error(path, "missing required field"); return; }
            bool engineering = m.YoungsModulus != null || m.PoissonRatio != null;
            bool lame = m.Mu != null || m.Lambda != null;
            if (engineering && lame) Error(path, "give youngsModulus and poissonRatio, or mu and lambda, not both");
            else if (!engineering && !lame) Error(path, "give youngsModulus and poissonRatio, or mu and lambda");
            else if (engineering)
            {
                if (m.YoungsModulus is float e) Positive(e, P(path, "youngsModulus"));
                else Error(P(path, "youngsModulus"), "missing: poissonRatio needs youngsModulus");
                if (m.PoissonRatio is float nu)
                {
                    if (!(nu > -1 && nu < 0.5f)) Error(P(path, "poissonRatio"), $"must be in (-1, 0.5), got {F(nu)}");
                }
                else Error(P(path, "poissonRatio"), "missing: youngsModulus needs poissonRatio");
            }
            else
            {
                float mu = m.Mu ?? 0;
                if (m.Mu == null) Error(P(path, "mu"), "missing: lambda needs mu");
                else Positive(mu, P(path, "mu"));
                if (m.Lambda is float lambda)
                {
                    // A positive bulk modulus K = lambda + 2 mu / 3 keeps the material stable.
                    if (Finite(lambda, P(path, "lambda")) && m.Mu != null && !(lambda + 2f * mu / 3f > 0))
                        Error(P(path, "lambda"), $"must be > -2 mu / 3 (a positive bulk modulus), got {F(lambda)}");
                }
                else Error(P(path, "lambda"), "missing: mu needs lambda");
            }
            Positive(m.Density, P(path, "density"));
        }
    }
}
