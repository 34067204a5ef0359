using System;
using System.Globalization;
using System.IO;
using System.Numerics;
using System.Text;
using Fulcrum.Scenes;

namespace Fulcrum.Runner;

/// <summary>
/// Writes the trace files of DESIGN.md for one run: FILE.csv (one row per body per recorded
/// step, world frame: origin, rotation, velocity of the centre of mass, angular velocity),
/// FILE.world.csv (one row per recorded step) and, when soft bodies exist, FILE.soft.csv.
/// Floats are written with round-trip formatting so a trace reproduces the run bit for bit.
/// </summary>
sealed class TraceWriter : IDisposable
{
    public const string BodyHeader = "step,time,name,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz";
    public const string WorldHeader = "step,time,kineticEnergy,potentialEnergy,maxPenetration,maxJointError,contacts,awakeBodies,stepMs";
    public const string SoftHeader = "step,time,name,cx,cy,cz,volumeRatio,minJ,energy";

    readonly TextWriter _bodies;
    readonly TextWriter _world;
    readonly TextWriter? _soft;
    readonly int _probeColumns;
    readonly StringBuilder _line = new(256);

    public TraceWriter(string path, SceneInstance scene, ISoftBodyMonitor? soft)
    {
        string stem = path.EndsWith(".csv", StringComparison.OrdinalIgnoreCase) ? path[..^4] : path;
        BodyPath = path;
        WorldPath = stem + ".world.csv";
        string? dir = Path.GetDirectoryName(Path.GetFullPath(path));
        if (dir != null) Directory.CreateDirectory(dir);
        _bodies = Open(BodyPath);
        _bodies.Write(BodyHeader + "\n");
        _world = Open(WorldPath);
        _world.Write(WorldHeader + "\n");
        if (soft != null)
        {
            SoftPath = stem + ".soft.csv";
            _soft = Open(SoftPath);
            foreach (SceneSoftBody s in scene.SoftBodies) _probeColumns = Math.Max(_probeColumns, s.Probes.Count);
            var header = new StringBuilder(SoftHeader);
            for (int p = 0; p < _probeColumns; p++) header.Append($",probe{p}x,probe{p}y,probe{p}z");
            _soft.Write(header.Append('\n').ToString());
        }
    }

    public string BodyPath { get; }
    public string WorldPath { get; }
    public string? SoftPath { get; }

    static StreamWriter Open(string path) => new(path, false, new UTF8Encoding(false), 1 << 16);

    static string F(float f) => f.ToString("R", CultureInfo.InvariantCulture);

    public void Record(long step, SceneInstance scene, ISoftBodyMonitor? soft, float stepMs)
    {
        World world = scene.World;
        string time = F((float)world.Time);
        string stepText = step.ToString(CultureInfo.InvariantCulture);
        for (int i = 0; i < scene.BodyHandles.Count; i++)
        {
            BodyRef b = world.GetBody(scene.BodyHandles[i]);
            Vector3 p = b.Position, v = b.LinearVelocity, w = b.AngularVelocity;
            Quaternion q = b.Rotation;
            _line.Clear().Append(stepText).Append(',').Append(time).Append(',').Append(Csv(scene.BodyName(i)));
            Append(p); Append(q); Append(v); Append(w);
            _bodies.Write(_line.Append('\n'));
        }
        _line.Clear().Append(stepText).Append(',').Append(time)
            .Append(',').Append(F(RigidEnergy.Kinetic(world)))
            .Append(',').Append(F(RigidEnergy.Potential(world)))
            .Append(',').Append(F(world.MaxPenetration))
            .Append(',').Append(F(world.MaxJointError))
            .Append(',').Append(world.ContactCount.ToString(CultureInfo.InvariantCulture))
            .Append(',').Append(world.AwakeBodyCount.ToString(CultureInfo.InvariantCulture))
            .Append(',').Append(F(stepMs));
        _world.Write(_line.Append('\n'));
        if (_soft == null || soft == null) return;
        for (int s = 0; s < soft.Count; s++)
        {
            SoftBodySample sample = soft.Sample(s);
            _line.Clear().Append(stepText).Append(',').Append(time).Append(',').Append(Csv(soft.Name(s)));
            Append(sample.Center);
            _line.Append(',').Append(F(sample.VolumeRatio)).Append(',').Append(F(sample.MinJ)).Append(',').Append(F(sample.Energy));
            for (int p = 0; p < _probeColumns; p++)
            {
                if (p < sample.Probes.Length) Append(sample.Probes[p]);
                else _line.Append(",,,");
            }
            _soft.Write(_line.Append('\n'));
        }
    }

    void Append(Vector3 v) => _line.Append(',').Append(F(v.X)).Append(',').Append(F(v.Y)).Append(',').Append(F(v.Z));

    void Append(Quaternion q) => _line.Append(',').Append(F(q.X)).Append(',').Append(F(q.Y)).Append(',').Append(F(q.Z)).Append(',').Append(F(q.W));

    // RFC 4180: quote a field holding a comma, quote or line break.
    static string Csv(string s) =>
        s.AsSpan().IndexOfAny(",\"\n\r") < 0 ? s : "\"" + s.Replace("\"", "\"\"") + "\"";

    public void Dispose()
    {
        _bodies.Dispose();
        _world.Dispose();
        _soft?.Dispose();
    }
}
