using System.IO;
using System.Numerics;
using Fulcrum.Scenes;
using Fulcrum.SoftBodies;

namespace Fulcrum.Runner;

/// <summary>One soft body's state for the trace and the summary.</summary>
public readonly record struct SoftBodySample(Vector3 Center, float VolumeRatio, float MinJ, float Energy, Vector3[] Probes);

/// <summary>
/// What the runner needs from the soft bodies of a scene: create them in the world and
/// sample them after each step (FILE.soft.csv, the volume error and min J of the summary).
/// Fulcrum.SoftBodies implements it; see <see cref="SoftBodySupport"/>.
/// </summary>
public interface ISoftBodyMonitor
{
    /// <summary>Soft bodies in the scene's order.</summary>
    int Count { get; }

    /// <summary>The name of soft body <paramref name="index"/>.</summary>
    string Name(int index);

    /// <summary>The state of soft body <paramref name="index"/> now.</summary>
    SoftBodySample Sample(int index);
}

/// <summary>
/// Where the soft-body assembly joins the runner: creates a scene's soft bodies with
/// <see cref="SceneSoftBodyBuilder"/> and samples them for traces, summaries and sweeps.
/// </summary>
public static class SoftBodySupport
{
    /// <summary>
    /// Creates the scene's soft bodies and returns a monitor over them; null when there are
    /// none. <paramref name="substeps"/> and <paramref name="iterations"/> (0: the soft bodies'
    /// own defaults) set their XPBD solver, as the runner's --substeps and --iterations do.
    /// Mesh files (tetgen, obj) are read relative to <paramref name="scenePath"/>'s folder.
    /// </summary>
    public static ISoftBodyMonitor? Attach(SceneInstance scene, string scenePath, out string? note, int substeps = 0, int iterations = 0)
    {
        note = null;
        if (scene.SoftBodies.Count == 0) return null;
        string? directory = Path.GetDirectoryName(Path.GetFullPath(scenePath));
        try
        {
            return new Monitor(scene.World, SceneSoftBodyBuilder.Build(scene, substeps, iterations, directory));
        }
        catch (SceneException e)
        {
            // A mesh file that is missing, not a regular file, or garbage: one line naming it.
            throw new UsageException($"{scenePath}: {e.Errors[0]}", Cli.ExitScene);
        }
    }

    sealed class Monitor : ISoftBodyMonitor
    {
        readonly World _world;
        readonly SoftBodyHandle[] _handles;

        public Monitor(World world, SoftBodyHandle[] handles)
        {
            _world = world;
            _handles = handles;
        }

        public int Count => _handles.Length;

        public string Name(int index) => _world.GetSoftBody(_handles[index]).Name ?? $"soft{index}";

        // energy: elastic (strain) plus kinetic energy of the soft body, J.
        public SoftBodySample Sample(int index)
        {
            SoftBody body = _world.GetSoftBody(_handles[index]);
            SoftBodyStats stats = body.ComputeStats();
            var probes = new Vector3[body.ProbeCount];
            for (int p = 0; p < probes.Length; p++) probes[p] = body.GetProbe(p);
            return new SoftBodySample(stats.Centroid, stats.VolumeRatio, stats.MinJ, stats.StrainEnergy + stats.KineticEnergy, probes);
        }
    }
}
