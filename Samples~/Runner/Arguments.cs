using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace Fulcrum.Runner;

/// <summary>
/// The flags of one command: <c>--name value</c> pairs, valueless switches (<c>--live</c>,
/// present or not) and positional arguments. Every accessor checks its value and throws a
/// <see cref="UsageException"/> naming the flag.
/// </summary>
sealed class Arguments
{
    readonly Dictionary<string, string> _flags = new();
    readonly List<string> _positional = new();
    readonly HashSet<string> _switches = new();

    public Arguments(string command, IReadOnlyList<string> args, int start, params string[] allowed)
        : this(command, args, start, allowed, Array.Empty<string>())
    {
    }

    /// <summary>Flags that take a value (<paramref name="allowed"/>) and switches that take none (<paramref name="switches"/>).</summary>
    public Arguments(string command, IReadOnlyList<string> args, int start, string[] allowed, string[] switches)
    {
        Command = command;
        for (int i = start; i < args.Count; i++)
        {
            string a = args[i];
            if (!a.StartsWith("--", StringComparison.Ordinal) || a.Length == 2)
            {
                _positional.Add(a);
                continue;
            }
            string name = a;
            string? value = null;
            int eq = a.IndexOf('=');
            if (eq > 0)
            {
                name = a[..eq];
                value = a[(eq + 1)..];
            }
            if (Array.IndexOf(switches, name) >= 0)
            {
                if (value != null) throw new UsageException($"{name}: takes no value, got '{Fulcrum.Scenes.SceneError.Clip(value)}'");
                if (!_switches.Add(name)) throw new UsageException($"{name}: given twice");
                continue;
            }
            if (Array.IndexOf(allowed, name) < 0)
                throw new UsageException($"{command}: unknown flag '{name}' (expected {string.Join(", ", allowed.Concat(switches))})");
            if (value == null)
            {
                if (i + 1 >= args.Count) throw new UsageException($"{name}: missing value");
                value = args[++i];
            }
            if (!_flags.TryAdd(name, value)) throw new UsageException($"{name}: given twice");
        }
    }

    public string Command { get; }

    public IReadOnlyList<string> Positional => _positional;

    /// <summary>Whether a flag (with its value) or a switch was given.</summary>
    public bool Has(string flag) => _flags.ContainsKey(flag) || _switches.Contains(flag);

    public string? String(string flag) => _flags.TryGetValue(flag, out string? v) ? v : null;

    /// <summary>The one positional argument the command takes (the scene file).</summary>
    public string Scene()
    {
        if (_positional.Count == 0) throw new UsageException($"{Command}: missing SCENE.json");
        if (_positional.Count > 1) throw new UsageException($"{Command}: unexpected argument '{_positional[1]}'");
        return _positional[0];
    }

    public int? Int(string flag, int min)
    {
        if (String(flag) is not string s) return null;
        if (!int.TryParse(s, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out int v) || v < min)
            throw new UsageException($"{flag}: expected an integer >= {min}, got '{s}'");
        return v;
    }

    /// <summary>An integer flag in [min, max] (the caps of <see cref="Limits"/>), or null when absent.</summary>
    public int? Int(string flag, int min, int max, string limit)
    {
        if (String(flag) is not string s) return null;
        if (!int.TryParse(s, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out int v) || v < min)
            throw new UsageException($"{flag}: expected an integer >= {min}, got '{Fulcrum.Scenes.SceneError.Clip(s)}'");
        if (v > max)
            throw new UsageException($"{flag}: expected an integer in {min}..{max} ({limit}), got '{Fulcrum.Scenes.SceneError.Clip(s)}'");
        return v;
    }

    /// <summary>A number flag in [min, max], or null when absent.</summary>
    public float? FloatInRange(string flag, float min, float max, string limit)
    {
        if (String(flag) is not string s) return null;
        if (!float.TryParse(s, NumberStyles.Float, CultureInfo.InvariantCulture, out float v) || !float.IsFinite(v) || !(v > 0))
            throw new UsageException($"{flag}: expected a number > 0, got '{Fulcrum.Scenes.SceneError.Clip(s)}'");
        if (!(v >= min && v <= max))
            throw new UsageException($"{flag}: expected a number in [{min:G}, {max:G}] ({limit}), got '{Fulcrum.Scenes.SceneError.Clip(s)}'");
        return v;
    }

    public float? PositiveFloat(string flag)
    {
        if (String(flag) is not string s) return null;
        if (!float.TryParse(s, NumberStyles.Float, CultureInfo.InvariantCulture, out float v) || !float.IsFinite(v) || !(v > 0))
            throw new UsageException($"{flag}: expected a number > 0, got '{s}'");
        return v;
    }

    public SolverType? Solver(string flag)
    {
        if (String(flag) is not string s) return null;
        return ParseSolver(flag, s);
    }

    public static SolverType ParseSolver(string flag, string s) =>
        Scenes.SceneNames.TryParse(s, out SolverType t) ? t : throw new UsageException($"{flag}: expected pgs or tgs, got '{s}'");

    public List<SolverType>? Solvers(string flag)
    {
        if (String(flag) is not string s) return null;
        var list = new List<SolverType>();
        foreach (string part in Split(flag, s))
        {
            SolverType t = ParseSolver(flag, part);
            if (!list.Contains(t)) list.Add(t);
        }
        return list;
    }

    public List<int>? Ints(string flag, int min)
    {
        if (String(flag) is not string s) return null;
        var list = new List<int>();
        foreach (string part in Split(flag, s))
        {
            if (!int.TryParse(part, NumberStyles.None, CultureInfo.InvariantCulture, out int v) || v < min)
                throw new UsageException($"{flag}: expected a comma-separated list of integers >= {min}, got '{s}'");
            if (!list.Contains(v)) list.Add(v);
        }
        return list;
    }

    static string[] Split(string flag, string s)
    {
        string[] parts = s.Split(',', StringSplitOptions.TrimEntries);
        foreach (string p in parts)
            if (p.Length == 0) throw new UsageException($"{flag}: empty item in '{s}'");
        return parts;
    }
}
