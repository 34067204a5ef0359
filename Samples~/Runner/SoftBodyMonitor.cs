using System.Numerics;
using Fulcrum.Scenes;

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
/// The seam where the soft-body assembly joins the runner. Until Fulcrum.SoftBodies can build
/// a <see cref="SceneSoftBody"/>, scenes with soft bodies run their rigid part only and say so.
/// To wire it: reference Fulcrum.SoftBodies from the runner, create the soft bodies in
/// <see cref="Attach"/> and return a monitor over them; traces and summaries pick it up.
/// </summary>
public static class SoftBodySupport
{
    /// <summary>Creates the scene's soft bodies; null (and a note) when there are none or they cannot be built yet.</summary>
    public static ISoftBodyMonitor? Attach(SceneInstance scene, out string? note)
    {
        note = null;
        if (scene.SoftBodies.Count == 0) return null;
        note = $"{scene.SoftBodies.Count} soft bod{(scene.SoftBodies.Count == 1 ? "y" : "ies")} skipped: soft bodies are not wired into the runner yet";
        return null;
    }
}
