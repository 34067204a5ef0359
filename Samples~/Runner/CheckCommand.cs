using System;
using System.Collections.Generic;
using System.IO;
using Fulcrum.Scenes;

namespace Fulcrum.Runner;

/// <summary><c>fulcrum check SCENE.json</c>: validates only, printing every error with its JSON path.</summary>
static class CheckCommand
{
    public static int Run(Arguments a, TextWriter output, TextWriter error)
    {
        string path = a.Scene();
        string text = SceneSetup.ReadText(path);
        IReadOnlyList<SceneError> errors = SceneFile.Check(text, out SceneDocument? doc);
        foreach (SceneError e in errors) error.WriteLine($"{path}: {e}");
        if (errors.Count > 0)
        {
            error.WriteLine($"{path}: {errors.Count} error{(errors.Count == 1 ? "" : "s")}");
            return Cli.ExitScene;
        }
        SceneExpansion x = doc!.Expand();
        output.WriteLine($"{path}: ok ({Count(x.Bodies.Count, "body", "bodies")}, {Count(x.Joints.Count, "joint", "joints")}, {Count(doc.SoftBodies.Count, "soft body", "soft bodies")})");
        return Cli.ExitOk;
    }

    public static string Count(int n, string one, string many) => $"{n} {(n == 1 ? one : many)}";
}
