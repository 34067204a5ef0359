using System;
using System.IO;
using Fulcrum.Scenes;

namespace Fulcrum.Runner;

/// <summary>
/// <c>fulcrum run SCENE.json --record OUT.frec</c>: the run command's recording for the
/// browser viewer (Documentation~/RecordingFormat.md, Documentation~/Runner.md). Kept apart
/// from <see cref="RunCommand"/>, which only opens it and passes <see cref="Session.AfterStep"/>
/// to the run loop.
/// </summary>
static class RecordCommand
{
    /// <summary>The flag.</summary>
    public const string Flag = "--record";

    /// <summary>The --record path, checked before anything runs; null when the flag is absent.</summary>
    public static string? PathOf(Arguments a)
    {
        string? path = a.String(Flag);
        if (path == null) return null;
        if (path.Length == 0) throw new UsageException($"{Flag}: expected a file name");
        if (Directory.Exists(path)) throw new UsageException($"{Flag}: '{path}' is a directory; give a file name such as {System.IO.Path.Combine(path, "run.frec")}");
        return path;
    }

    /// <summary>
    /// Opens the recording of <paramref name="scene"/> and writes its header and frame 0.
    /// Frames follow every <paramref name="every"/>-th step and the last one (<paramref name="steps"/>).
    /// With <paramref name="live"/> the recording goes to the live viewers, and to the file
    /// <paramref name="path"/> as well when it is given.
    /// </summary>
    public static Session Open(string? path, SceneInstance scene, int steps, int every, LiveServer? live = null)
    {
        Stream? file = path != null ? OpenFile(path) : null;
        Stream stream = live != null ? live.OpenStream(file) : file ?? throw new ArgumentNullException(nameof(path));
        var names = new System.Collections.Generic.Dictionary<BodyHandle, string>();
        for (int i = 0; i < scene.BodyHandles.Count; i++) names[scene.BodyHandles[i]] = scene.BodyName(i);
        var recorder = new Recorder(scene.World, scene.Timestep, stream, ownsStream: true,
            h => names.TryGetValue(h, out string? n) ? n : null);
        recorder.Record(0);
        return new Session(path, recorder, steps, every);
    }

    static FileStream OpenFile(string path)
    {
        try
        {
            string? dir = System.IO.Path.GetDirectoryName(System.IO.Path.GetFullPath(path));
            if (dir != null) Directory.CreateDirectory(dir);
            return new FileStream(path, FileMode.Create, FileAccess.Write, FileShare.Read, 1 << 16);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
        {
            throw new UsageException($"{Flag}: cannot write '{path}': {e.Message}");
        }
    }

    /// <summary>An open recording of one run.</summary>
    public sealed class Session : IDisposable
    {
        readonly int _steps, _every;

        public Session(string? path, Recorder recorder, int steps, int every)
        {
            Path = path;
            Recorder = recorder;
            _steps = steps;
            _every = every;
            // One delegate for the whole run, so that the loop's callback allocates nothing per step.
            AfterStep = Record;
        }

        /// <summary>The --record file, or null for a live run without one.</summary>
        public string? Path { get; }
        public Recorder Recorder { get; }

        /// <summary>The run loop's per-step callback (step numbers from 1).</summary>
        public Action<int> AfterStep { get; }

        void Record(int step)
        {
            if (step % _every == 0 || step == _steps) Recorder.Record(step);
        }

        /// <summary>One line for the run's output: file, frames, size and what recording cost per frame.</summary>
        public string Summary() =>
            $"recording: {Path ?? "live"}, {Recorder.FrameCount} frames, {Recorder.BytesWritten / 1024.0:F1} KiB, " +
            $"{Recorder.RecordMilliseconds / Math.Max(1, Recorder.FrameCount):F3} ms/frame to record" +
            (Path != null ? $"; view it with 'fulcrum view {Path}'" : "");

        public void Dispose() => Recorder.Dispose();
    }
}
