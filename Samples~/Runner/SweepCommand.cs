using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Numerics;
using System.Text;
using Fulcrum.Scenes;

namespace Fulcrum.Runner;

/// <summary>
/// <c>fulcrum sweep SCENE.json [--solver pgs,tgs] [--iterations 1,2,4,8,16] [--substeps 1,2,4,8] [--out DIR]</c>:
/// runs the scene once per solver setting and writes DIR/sweep.csv and DIR/sweep.svg (error
/// against ms/step, Pareto front marked). referenceError is the RMS, over every step and
/// dynamic body, of the distance between a body's position and its position in a converged
/// reference run of the same scene (TGS, 16 iterations x 8 substeps, same dt). PGS ignores
/// substeps, so it runs once per iteration count (written with substeps 1).
/// Extensions beyond the contract: --seconds S | --steps N (default 2 s), --dt X, --threads N.
/// </summary>
static class SweepCommand
{
    public static readonly string[] Flags =
        { "--solver", "--iterations", "--substeps", "--out", "--seconds", "--steps", "--dt", "--threads", "--soft-solver" };

    public const float DefaultSeconds = 2f;
    public const int ReferenceIterations = 16, ReferenceSubsteps = 8;

    /// <summary>
    /// The soft bodies' reference: XPBD converges with smaller substeps rather than more
    /// iterations (Macklin et al. 2019, "Small Steps in Physics Simulation"), so 60 substeps
    /// (1/3600 s at 60 Hz) of 2 iterations each.
    /// </summary>
    public const int ReferenceSoftSubsteps = 60, ReferenceSoftIterations = 2;

    public static int Run(Arguments a, TextWriter output)
    {
        string path = a.Scene();
        List<SolverType> solvers = a.Solvers("--solver") ?? new List<SolverType> { SolverType.Pgs, SolverType.Tgs };
        List<int> iterations = a.Ints("--iterations", 1) ?? new List<int> { 1, 2, 4, 8, 16 };
        List<int> substeps = a.Ints("--substeps", 1) ?? new List<int> { 1, 2, 4, 8 };
        string outDir = a.String("--out") ?? "sweep-" + Path.GetFileNameWithoutExtension(path);
        if (outDir.Length == 0) throw new UsageException("--out: expected a directory");
        if (File.Exists(outDir)) throw new UsageException($"--out: '{outDir}' is a file; give a directory");
        WorldSettings settings = SceneSetup.Settings(a);
        // A sweep prices solver settings: sleeping would make a settled scene cost nothing
        // whatever the setting, so every run (the reference too) keeps its bodies awake.
        settings.EnableSleeping = false;
        SceneDocument doc = SceneSetup.Load(path);
        if (a.PositiveFloat("--dt") is float dt) doc.Timestep = dt;
        // The soft solvers to sweep: both where every soft body has tets (Newton solves tets
        // only), and then the converged reference is Newton's; XPBD alone otherwise.
        bool anySoft = doc.SoftBodies.Count > 0, allTets = true;
        foreach (SceneSoftBody s in doc.SoftBodies) allTets &= s.Mesh?.Type != SceneSoftMeshType.Cloth;
        List<string> softSolvers = SoftSolvers(a.String("--soft-solver"), anySoft, allTets, path);
        string referenceSoft = anySoft && allTets ? "newton" : "xpbd";
        int steps = SceneSetup.Steps(a, doc.Timestep, DefaultSeconds);

        // The reference run doubles as the check that the scene builds at all.
        SceneDocument refDoc = With(doc, SolverType.Tgs, ReferenceIterations, ReferenceSubsteps, referenceSoft);
        SceneInstance reference = SceneSetup.Build(path, refDoc, settings);
        ISoftBodyMonitor? refSoft = SoftBodySupport.Attach(reference, path, out string? softNote, ReferenceSoftSubsteps, ReferenceSoftIterations);
        List<int> dynamic = DynamicBodies(reference);
        int tracked = dynamic.Count + SoftPointCount(refSoft);
        if ((long)steps * tracked > 20_000_000)
            throw new UsageException($"--steps: {steps} steps x {tracked} tracked points is too long a reference to keep; use fewer steps");
        var refPositions = new Vector3[steps * tracked];
        SceneRun.Run(reference, steps, doc.Timestep, afterStep: n => Record(reference, dynamic, refSoft, refPositions, tracked, n));

        output.WriteLine($"sweep: {path}, {steps} steps of {SceneSetup.F(doc.Timestep)} s, reference tgs {ReferenceIterations}x{ReferenceSubsteps}" +
                         (refSoft != null ? $", soft bodies {(referenceSoft == "newton" ? "Newton" : "XPBD")} {ReferenceSoftSubsteps} substeps x {ReferenceSoftIterations} iterations; swept substeps and iterations set the soft bodies' solver too (soft solvers: {string.Join(", ", softSolvers)})" : ""));
        if (softNote != null) output.WriteLine("note: " + softNote);

        // Two passes over the settings, the first untimed: every code path is JIT-optimised
        // before it is measured, so the first rows are not priced at unoptimised code.
        var points = new List<SweepPoint>();
        for (int pass = 0; pass < 2; pass++)
        foreach (string softSolver in softSolvers)
        foreach (SolverType solver in solvers)
        foreach (int it in iterations)
        foreach (int sub in solver == SolverType.Pgs ? new List<int> { 1 } : substeps)
        {
            if (pass == 0)
            {
                SceneInstance warm = SceneSetup.Build(path, With(doc, solver, it, sub, softSolver), settings);
                SceneRun.Run(warm, Math.Min(steps, 60), doc.Timestep, SoftBodySupport.Attach(warm, path, out _, sub, it));
                continue;
            }
            SceneInstance scene = SceneSetup.Build(path, With(doc, solver, it, sub, softSolver), settings);
            ISoftBodyMonitor? soft = SoftBodySupport.Attach(scene, path, out _, sub, it);
            double sum = 0;
            RunResult r = SceneRun.Run(scene, steps, doc.Timestep, soft, afterStep: n => sum += SquaredDistance(scene, dynamic, soft, refPositions, tracked, n));
            float? referenceError = tracked > 0 ? (float)Math.Sqrt(sum / ((double)steps * tracked)) : null;
            points.Add(new SweepPoint(solver, it, sub, doc.Timestep, r.MedianMs, r.MaxPenetration, r.MaxJointError, referenceError, r.EnergyDrift, r.VolumeError,
                anySoft ? softSolver : ""));
        }

        Directory.CreateDirectory(outDir);
        string csvPath = Path.Combine(outDir, "sweep.csv"), svgPath = Path.Combine(outDir, "sweep.svg");
        File.WriteAllText(csvPath, Csv(points), new UTF8Encoding(false));
        (string errorName, Func<SweepPoint, double> error) = ErrorMetric(points);
        File.WriteAllText(svgPath, SweepPlot.Svg($"{Path.GetFileName(path)}: {errorName} against cost", errorName, points, error), new UTF8Encoding(false));

        var table = new TextTable("solver", "iterations", "substeps", "ms/step", "max penetration (m)", "max joint error (m)", "reference error (m)", "energy drift (J)", "soft solver");
        foreach (SweepPoint p in points)
            table.Add(SceneNames.Of(p.Solver), p.Iterations.ToString(CultureInfo.InvariantCulture), p.Substeps.ToString(CultureInfo.InvariantCulture),
                TextTable.Number(p.MsPerStep), TextTable.Number(p.MaxPenetration), TextTable.Number(p.MaxJointError),
                TextTable.Number(p.ReferenceError), TextTable.Number(p.EnergyDrift), p.SoftSolver.Length > 0 ? p.SoftSolver : "-");
        table.Write(output);
        output.WriteLine($"wrote {csvPath}, {svgPath}");
        return Cli.ExitOk;
    }

    static SceneDocument With(SceneDocument doc, SolverType solver, int iterations, int substeps, string softSolver)
    {
        // Reparse a saved copy: the exact round trip makes this a deep clone.
        SceneDocument copy = SceneFile.Parse(SceneFile.Save(doc));
        copy.Solver.Type = solver;
        copy.Solver.Iterations = iterations;
        copy.Solver.Substeps = substeps;
        foreach (SceneSoftBody s in copy.SoftBodies) s.Solver = softSolver;
        return copy;
    }

    // --soft-solver xpbd,newton: checked names; the default is both where Newton applies.
    static List<string> SoftSolvers(string? flag, bool anySoft, bool allTets, string path)
    {
        if (flag == null) return anySoft && allTets ? new List<string> { "xpbd", "newton" } : new List<string> { "xpbd" };
        var list = new List<string>();
        foreach (string name in flag.Split(','))
        {
            string n = name.Trim();
            if (n != "xpbd" && n != "newton") throw new UsageException($"--soft-solver: unknown solver '{n}' (expected xpbd or newton)");
            if (n == "newton" && !allTets) throw new UsageException($"--soft-solver: newton solves tetrahedra; {path} has a cloth (shell) body");
            if (!list.Contains(n)) list.Add(n);
        }
        if (list.Count == 0) throw new UsageException("--soft-solver: expected xpbd, newton or both");
        return list;
    }

    static List<int> DynamicBodies(SceneInstance scene)
    {
        var list = new List<int>();
        for (int i = 0; i < scene.BodyHandles.Count; i++)
            if (scene.World.GetBody(scene.BodyHandles[i]).Type == BodyType.Dynamic) list.Add(i);
        return list;
    }

    // Tracked points: every dynamic body's origin, then each soft body's centroid and probes
    // (a fixed number per run: counted once, before the runs).
    static int SoftPointCount(ISoftBodyMonitor? soft)
    {
        int n = 0;
        for (int s = 0; soft != null && s < soft.Count; s++) n += 1 + soft.Sample(s).Probes.Length;
        return n;
    }

    static void Points(SceneInstance scene, List<int> dynamic, ISoftBodyMonitor? soft, Span<Vector3> into)
    {
        int k = 0;
        foreach (int body in dynamic) into[k++] = scene.World.GetBody(scene.BodyHandles[body]).Position;
        for (int s = 0; soft != null && s < soft.Count; s++)
        {
            SoftBodySample sample = soft.Sample(s);
            into[k++] = sample.Center;
            foreach (Vector3 probe in sample.Probes) into[k++] = probe;
        }
    }

    static void Record(SceneInstance scene, List<int> dynamic, ISoftBodyMonitor? soft, Vector3[] into, int tracked, int step)
    {
        Points(scene, dynamic, soft, into.AsSpan((step - 1) * tracked, tracked));
    }

    static double SquaredDistance(SceneInstance scene, List<int> dynamic, ISoftBodyMonitor? soft, Vector3[] reference, int tracked, int step)
    {
        Span<Vector3> now = tracked <= 256 ? stackalloc Vector3[tracked] : new Vector3[tracked];
        Points(scene, dynamic, soft, now);
        int row = (step - 1) * tracked;
        double sum = 0;
        for (int k = 0; k < tracked; k++) sum += Vector3.DistanceSquared(now[k], reference[row + k]);
        return sum;
    }

    // The plot's y axis: the reference error where it applies, else the joint error, else penetration.
    static (string, Func<SweepPoint, double>) ErrorMetric(List<SweepPoint> points)
    {
        if (points.Count > 0 && points[0].ReferenceError != null) return ("reference error (m)", p => p.ReferenceError ?? 0);
        if (points.Count > 0 && points[0].MaxJointError != null) return ("max joint error (m)", p => p.MaxJointError ?? 0);
        return ("max penetration (m)", p => p.MaxPenetration);
    }

    static string Csv(List<SweepPoint> points)
    {
        var sb = new StringBuilder(SweepPoint.Header).Append('\n');
        foreach (SweepPoint p in points)
            sb.Append(SceneNames.Of(p.Solver)).Append(',')
              .Append(p.Iterations.ToString(CultureInfo.InvariantCulture)).Append(',')
              .Append(p.Substeps.ToString(CultureInfo.InvariantCulture)).Append(',')
              .Append(SceneSetup.F(p.Dt)).Append(',')
              .Append(p.MsPerStep.ToString("R", CultureInfo.InvariantCulture)).Append(',')
              .Append(SceneSetup.F(p.MaxPenetration)).Append(',')
              .Append(Opt(p.MaxJointError)).Append(',')
              .Append(Opt(p.ReferenceError)).Append(',')
              .Append(SceneSetup.F(p.EnergyDrift)).Append(',')
              .Append(Opt(p.VolumeError)).Append(',')
              .Append(p.SoftSolver).Append('\n');
        return sb.ToString();
    }

    static string Opt(float? v) => v is float f ? SceneSetup.F(f) : "";
}
