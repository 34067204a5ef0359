using System;
using System.Buffers.Binary;
using System.Diagnostics;
using System.IO;
using System.Numerics;
using System.Text;
using Fulcrum.Collision;
using Fulcrum.Dynamics;
using Fulcrum.SoftBodies;

namespace Fulcrum.Runner;

/// <summary>
/// Writes a world to a <c>.frec</c> recording for the browser viewer
/// (Documentation~/RecordingFormat.md): the constructor writes the header (bodies, shapes
/// with their geometry, joints, soft-body meshes) and <see cref="Record"/> appends one frame
/// (poses, sleeping flags, contact points, joint frames and errors, soft-body vertices,
/// element J and strain, the step's stage times, energies).
/// <para>
/// What exists when the recorder is created is what is recorded: bodies, joints and soft
/// bodies created later are not in the header and are left out of the frames (a removed
/// body is flagged, a removed joint is written as broken). Contacts involving such bodies
/// carry body index -1.
/// </para>
/// <para>
/// Cost: a frame is built in one reusable byte buffer and handed to the stream in one write,
/// so once the buffer has grown to the largest frame, recording allocates nothing per step.
/// With <see cref="Enabled"/> false, <see cref="Record"/> returns at once and allocates
/// nothing either (tests: RecorderTests).
/// </para>
/// </summary>
public sealed class Recorder : IDisposable
{
    readonly World _world;
    readonly Stream _stream;
    readonly bool _ownsStream;
    readonly int[] _bodySlots;        // header order -> body slot
    readonly int[] _bodyGenerations;
    readonly int[] _bodyIndexOfSlot;  // body slot -> header index, -1 when not recorded
    readonly int[] _jointSlots;
    readonly int[] _jointGenerations;
    readonly SoftBody[] _softBodies;
    readonly float[][] _elementJ;     // per soft body, reused every frame
    readonly float[][] _elementStrain;
    readonly ElementStrain[] _strain;
    byte[] _buffer = new byte[1 << 16];
    int _length;
    long _ticks;

    /// <summary>
    /// Writes the header of <paramref name="world"/> to <paramref name="stream"/>.
    /// <paramref name="bodyNames"/> (optional, by body slot) names bodies that have no name of
    /// their own in the world.
    /// </summary>
    /// <param name="world">The world to record; call between steps.</param>
    /// <param name="timestep">The fixed step the caller will use, s (written to the header; the world does not keep it).</param>
    /// <param name="stream">Where to write (a file stream, or memory in tests).</param>
    /// <param name="ownsStream">Whether <see cref="Dispose"/> closes <paramref name="stream"/>.</param>
    /// <param name="bodyNames">Names for unnamed bodies, or null.</param>
    public Recorder(World world, float timestep, Stream stream, bool ownsStream = true, Func<BodyHandle, string?>? bodyNames = null)
    {
        _world = world ?? throw new ArgumentNullException(nameof(world));
        _stream = stream ?? throw new ArgumentNullException(nameof(stream));
        _ownsStream = ownsStream;

        BodyStorage b = world.Bodies;
        _bodySlots = new int[b.ActiveCount];
        _bodyGenerations = new int[b.ActiveCount];
        for (int k = 0; k < b.ActiveCount; k++) _bodySlots[k] = b.Active[k];
        // Slot order, so that a scene's bodies appear in the order it created them.
        Array.Sort(_bodySlots);
        _bodyIndexOfSlot = new int[Math.Max(1, b.SlotCount)];
        Array.Fill(_bodyIndexOfSlot, -1);
        for (int k = 0; k < _bodySlots.Length; k++)
        {
            _bodyIndexOfSlot[_bodySlots[k]] = k;
            _bodyGenerations[k] = b.Generation[_bodySlots[k]];
        }

        JointStorage j = world.Joints;
        _jointSlots = new int[j.ActiveCount];
        _jointGenerations = new int[j.ActiveCount];
        for (int k = 0; k < j.ActiveCount; k++) _jointSlots[k] = j.Active[k];
        Array.Sort(_jointSlots);
        for (int k = 0; k < _jointSlots.Length; k++) _jointGenerations[k] = j.Generation[_jointSlots[k]];

        SoftBodySystem? soft = SoftBodySystem.Of(world);
        _softBodies = new SoftBody[soft?.Count ?? 0];
        _elementJ = new float[_softBodies.Length][];
        _elementStrain = new float[_softBodies.Length][];
        _strain = new ElementStrain[_softBodies.Length];
        for (int k = 0; k < _softBodies.Length; k++)
        {
            _softBodies[k] = soft![k];
            _elementJ[k] = new float[_softBodies[k].ElementCount];
            _elementStrain[k] = new float[_softBodies[k].ElementCount];
            _strain[k] = new ElementStrain(_softBodies[k].Mesh);
        }

        WriteHeader(timestep, bodyNames);
        Flush();
    }

    /// <summary>Whether <see cref="Record"/> writes frames; false makes it return at once (default true).</summary>
    public bool Enabled { get; set; } = true;

    /// <summary>Frames written so far.</summary>
    public int FrameCount { get; private set; }

    /// <summary>Bytes written so far, header included.</summary>
    public long BytesWritten { get; private set; }

    /// <summary>Time spent in <see cref="Record"/> writing frames, ms (what recording costs a run).</summary>
    public double RecordMilliseconds => _ticks * 1000.0 / Stopwatch.Frequency;

    /// <summary>
    /// Appends one frame: the world's state now, tagged with <paramref name="step"/> (0 for
    /// the state before the first step). Call between steps. Does nothing when
    /// <see cref="Enabled"/> is false.
    /// </summary>
    public void Record(long step)
    {
        if (!Enabled) return;
        long start = Stopwatch.GetTimestamp();
        _length = 4; // the frame's byte length goes here once it is known
        WriteFrame(step);
        BinaryPrimitives.WriteUInt32LittleEndian(_buffer, (uint)(_length - 4));
        Flush();
        FrameCount++;
        _ticks += Stopwatch.GetTimestamp() - start;
    }

    /// <summary>Flushes and, if the recorder owns it, closes the stream.</summary>
    public void Dispose()
    {
        _stream.Flush();
        if (_ownsStream) _stream.Dispose();
    }

    void WriteHeader(float timestep, Func<BodyHandle, string?>? bodyNames)
    {
        World w = _world;
        BodyStorage b = w.Bodies;
        ShapeStorage s = w.Shapes;
        _length = 0;
        for (int i = 0; i < 4; i++) U8(RecordingFormat.Magic[i]);
        U16(RecordingFormat.Version);
        U16(0);
        F32(timestep);
        V3(w.Gravity);

        U32(_bodySlots.Length);
        foreach (int i in _bodySlots)
        {
            string? name = b.Name[i] ?? bodyNames?.Invoke(new BodyHandle(i, b.Generation[i], w.Id));
            Str(name ?? $"#{i}");
            U8((byte)b.Type[i]);
            F32(b.Type[i] == BodyType.Dynamic ? b.Mass[i] : 0);
        }

        int shapeCount = 0;
        foreach (int i in _bodySlots)
            for (int sh = b.FirstShape[i]; sh >= 0; sh = s.NextInBody[sh]) shapeCount++;
        U32(shapeCount);
        for (int k = 0; k < _bodySlots.Length; k++)
            for (int sh = b.FirstShape[_bodySlots[k]]; sh >= 0; sh = s.NextInBody[sh])
                WriteShape(k, s.Geometry[sh], s.LocalPose[sh]);

        JointStorage j = w.Joints;
        U32(_jointSlots.Length);
        foreach (int slot in _jointSlots)
        {
            ref JointData d = ref j.Data[slot];
            Str(j.Name[slot] ?? $"joint{slot}");
            U8((byte)d.Kind);
            I32(BodyIndex(d.BodyA));
            I32(BodyIndex(d.BodyB));
        }

        U32(_softBodies.Length);
        for (int k = 0; k < _softBodies.Length; k++)
        {
            SoftBody sb = _softBodies[k];
            SoftMesh mesh = sb.Mesh;
            Str(sb.Name ?? $"soft{k}");
            U32(sb.VertexCount);
            ReadOnlySpan<int> elements = mesh.IsShell ? mesh.Triangles : mesh.Tetrahedra;
            U8(mesh.IsShell ? RecordingFormat.Triangles : RecordingFormat.Tetrahedra);
            U32(sb.ElementCount);
            foreach (int e in elements) U32(e);
            // The surface to draw: a shell is its own surface.
            ReadOnlySpan<int> surface = mesh.IsShell ? mesh.Triangles : mesh.SurfaceTriangles;
            U32(surface.Length / 3);
            foreach (int v in surface) U32(v);
        }
    }

    void WriteShape(int body, in ShapeGeometry g, in Mathematics.Pose local)
    {
        U32(body);
        U8((byte)g.Type);
        V3(local.Position);
        Q(local.Rotation);
        switch (g.Type)
        {
            case ShapeType.Sphere:
                F32(g.Radius);
                break;
            case ShapeType.Box:
                V3(g.HalfExtents);
                break;
            case ShapeType.Capsule:
                F32(g.Radius);
                F32(g.HalfHeight);
                break;
            case ShapeType.ConvexHull:
            {
                var hull = (ConvexHull)g.Data!;
                U32(hull.VertexCount);
                for (int v = 0; v < hull.VertexCount; v++) V3(hull.GetVertex(v));
                U32(hull.FaceCount);
                for (int f = 0; f < hull.FaceCount; f++)
                {
                    ReadOnlySpan<int> face = hull.GetFace(f);
                    U32(face.Length);
                    foreach (int v in face) U32(v);
                }
                break;
            }
            case ShapeType.Plane:
                V3(g.Normal);
                F32(g.Offset);
                break;
            case ShapeType.TriangleMesh:
            {
                var mesh = (TriangleMesh)g.Data!;
                U32(mesh.Vertices.Length);
                foreach (Vector3 v in mesh.Vertices) V3(v);
                U32(mesh.Indices.Length);
                foreach (int i in mesh.Indices) U32(i);
                break;
            }
            default:
                throw new NotSupportedException($"shape type {g.Type} has no recording layout");
        }
    }

    void WriteFrame(long step)
    {
        World w = _world;
        BodyStorage b = w.Bodies;
        U32((int)Math.Min(step, uint.MaxValue));
        F64(w.Time);
        StepProfile p = w.LastStepProfile;
        for (int stage = 0; stage < StepProfile.StageCount; stage++) F32((float)p[(StepStage)stage]);
        F32((float)p.Total);
        F32(Energy.Kinetic(w));
        F32(Energy.Potential(w));
        float softEnergy = 0;
        foreach (SoftBody sb in _softBodies)
            if (!sb.IsDestroyed)
            {
                // Strain, kinetic and gravitational potential (from the origin, as Energy.Potential
                // does for rigid bodies), so that a settling soft body does not look like a gain.
                SoftBodyStats stats = sb.ComputeStats();
                softEnergy += stats.StrainEnergy + stats.KineticEnergy - sb.TotalMass * sb.GravityScale * Vector3.Dot(w.Gravity, stats.Centroid);
            }
        F32(softEnergy);

        for (int k = 0; k < _bodySlots.Length; k++)
        {
            int i = _bodySlots[k];
            bool live = b.Generation[i] == _bodyGenerations[k] && b.ActiveIndex[i] >= 0;
            V3(b.Position[i]);
            Q(b.Rotation[i]);
            byte flags = 0;
            if (!live) flags |= RecordingFormat.BodyRemoved;
            else if (b.Type[i] != BodyType.Static && !b.Awake[i]) flags |= RecordingFormat.BodyAsleep;
            U8(flags);
        }

        ContactSet contacts = w.Contacts;
        int points = 0;
        for (int m = 0; m < contacts.ManifoldCount; m++) points += contacts[m].PointCount;
        U32(points);
        for (int m = 0; m < contacts.ManifoldCount; m++)
        {
            ref ContactManifold manifold = ref contacts[m];
            for (int k = 0; k < manifold.PointCount; k++)
            {
                ref ContactPoint cp = ref ContactManifold.Point(ref manifold, k);
                V3(cp.Position);
                V3(manifold.Normal);
                F32(cp.NormalImpulse);
                F32(cp.Separation);
                I32(BodyIndex(manifold.BodyA));
                I32(BodyIndex(manifold.BodyB));
            }
        }

        JointStorage j = w.Joints;
        for (int k = 0; k < _jointSlots.Length; k++)
        {
            int slot = _jointSlots[k];
            ref JointData d = ref j.Data[slot];
            bool live = j.Generation[slot] == _jointGenerations[k] && j.ActiveIndex[slot] >= 0;
            WorldFrame(d.BodyA, d.LocalAnchorA, d.LocalFrameA, out Vector3 anchorA, out Quaternion frameA);
            WorldFrame(d.BodyB, d.LocalAnchorB, d.LocalFrameB, out Vector3 anchorB, out Quaternion frameB);
            V3(anchorA);
            V3(anchorB);
            Q(frameA);
            Q(frameB);
            F32(d.Error);
            F32(d.Stress);
            U8(!live || d.Broken ? RecordingFormat.JointBroken : (byte)0);
        }

        for (int k = 0; k < _softBodies.Length; k++)
        {
            SoftBody sb = _softBodies[k];
            foreach (Vector3 x in sb.Positions) V3(x);
            float[] jOfElement = _elementJ[k], strain = _elementStrain[k];
            if (!sb.IsDestroyed)
            {
                sb.ComputeElementJ(jOfElement);
                _strain[k].Compute(sb.Positions, strain);
            }
            foreach (float value in jOfElement) F32(value);
            foreach (float value in strain) F32(value);
        }
    }

    // Joint anchors are relative to the body origin; for the world (-1) they are world points.
    void WorldFrame(int body, Vector3 localAnchor, Quaternion localFrame, out Vector3 anchor, out Quaternion frame)
    {
        if (body < 0)
        {
            anchor = localAnchor;
            frame = localFrame;
            return;
        }
        Quaternion r = _world.Bodies.Rotation[body];
        anchor = _world.Bodies.Position[body] + Vector3.Transform(localAnchor, r);
        frame = Quaternion.Normalize(r * localFrame);
    }

    // -1 for the world, for a body created after the header, and for one that reuses the
    // slot of a recorded body that was removed (its generation differs).
    int BodyIndex(int slot)
    {
        if (slot < 0 || slot >= _bodyIndexOfSlot.Length) return -1;
        int k = _bodyIndexOfSlot[slot];
        return k >= 0 && _world.Bodies.Generation[slot] == _bodyGenerations[k] ? k : -1;
    }

    void Flush()
    {
        _stream.Write(_buffer, 0, _length);
        BytesWritten += _length;
        _length = 0;
    }

    Span<byte> Take(int bytes)
    {
        if (_length + bytes > _buffer.Length) Array.Resize(ref _buffer, Math.Max(_buffer.Length * 2, _length + bytes));
        Span<byte> span = _buffer.AsSpan(_length, bytes);
        _length += bytes;
        return span;
    }

    void U8(byte v) => Take(1)[0] = v;
    void U16(ushort v) => BinaryPrimitives.WriteUInt16LittleEndian(Take(2), v);
    void U32(int v) => BinaryPrimitives.WriteUInt32LittleEndian(Take(4), (uint)v);
    void I32(int v) => BinaryPrimitives.WriteInt32LittleEndian(Take(4), v);
    void F32(float v) => BinaryPrimitives.WriteSingleLittleEndian(Take(4), v);
    void F64(double v) => BinaryPrimitives.WriteDoubleLittleEndian(Take(8), v);

    void V3(Vector3 v)
    {
        Span<byte> s = Take(12);
        BinaryPrimitives.WriteSingleLittleEndian(s, v.X);
        BinaryPrimitives.WriteSingleLittleEndian(s[4..], v.Y);
        BinaryPrimitives.WriteSingleLittleEndian(s[8..], v.Z);
    }

    void Q(Quaternion q)
    {
        Span<byte> s = Take(16);
        BinaryPrimitives.WriteSingleLittleEndian(s, q.X);
        BinaryPrimitives.WriteSingleLittleEndian(s[4..], q.Y);
        BinaryPrimitives.WriteSingleLittleEndian(s[8..], q.Z);
        BinaryPrimitives.WriteSingleLittleEndian(s[12..], q.W);
    }

    // UTF-8 with a u16 byte length; names are capped at 256 characters by the scene reader,
    // so the cap here only guards hand-made worlds.
    void Str(string s)
    {
        byte[] bytes = Encoding.UTF8.GetBytes(s.Length > 1024 ? s[..1024] : s);
        U16((ushort)bytes.Length);
        bytes.CopyTo(Take(bytes.Length));
    }
}
