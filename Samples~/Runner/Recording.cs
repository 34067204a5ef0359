using System;
using System.Buffers.Binary;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using System.Text;

namespace Fulcrum.Runner;

/// <summary>
/// A <c>.frec</c> recording read back whole (Documentation~/RecordingFormat.md): the header's
/// tables and every frame. For tests and tools; it allocates freely. The viewer has its own
/// reader (Viewer~/src/reader.ts) that decodes frames on demand.
/// </summary>
public sealed class Recording
{
    /// <summary>A recorded body: name, type and mass (0 unless dynamic), kg.</summary>
    public sealed record Body(string Name, BodyType Type, float Mass);

    /// <summary>
    /// A recorded shape of body <paramref name="Body"/> (index into <see cref="Bodies"/>), with
    /// its pose in the body frame. <paramref name="Size"/>: sphere (radius, 0, 0), box half
    /// extents, capsule (radius, half height, 0), plane normal. Hulls have
    /// <paramref name="Vertices"/> and <paramref name="Faces"/> (vertex loops); meshes have
    /// <paramref name="Vertices"/> and <paramref name="Indices"/>.
    /// </summary>
    public sealed record Shape(int Body, ShapeType Type, Vector3 Position, Quaternion Rotation, Vector3 Size, float Offset,
        Vector3[] Vertices, int[][] Faces, int[] Indices);

    /// <summary>A recorded joint: name, kind and the header indices of its bodies (-1: the world).</summary>
    public sealed record Joint(string Name, JointKind Kind, int BodyA, int BodyB);

    /// <summary>A recorded soft body: vertex count, elements (4 or 3 indices each) and the surface triangles to draw.</summary>
    public sealed record SoftBody(string Name, int VertexCount, int VerticesPerElement, int[] Elements, int[] Surface);

    /// <summary>One contact point: world position, normal, normal impulse (N s), separation (m), header body indices.</summary>
    public readonly record struct Contact(Vector3 Position, Vector3 Normal, float NormalImpulse, float Separation, int BodyA, int BodyB);

    /// <summary>One joint's state: world anchors and frames, position error (m), stress ratio, broken.</summary>
    public readonly record struct JointState(Vector3 AnchorA, Vector3 AnchorB, Quaternion FrameA, Quaternion FrameB, float Error, float Stress, bool Broken);

    /// <summary>One recorded step.</summary>
    public sealed class Frame
    {
        /// <summary>The step number (0: before the first step).</summary>
        public long Step;
        /// <summary>Simulated time, s.</summary>
        public double Time;
        /// <summary>Stage times of the step, ms, in <see cref="StepStage"/> order, then the total.</summary>
        public float[] Profile = Array.Empty<float>();
        /// <summary>Kinetic, potential (rigid bodies) and soft-body (strain + kinetic + potential) energy, J.</summary>
        public float Kinetic, Potential, SoftEnergy;
        /// <summary>Body poses in header order.</summary>
        public Vector3[] Positions = Array.Empty<Vector3>();
        /// <summary>Body rotations in header order.</summary>
        public Quaternion[] Rotations = Array.Empty<Quaternion>();
        /// <summary>Body flags (<see cref="RecordingFormat.BodyAsleep"/>, <see cref="RecordingFormat.BodyRemoved"/>).</summary>
        public byte[] BodyFlags = Array.Empty<byte>();
        /// <summary>Contact points.</summary>
        public Contact[] Contacts = Array.Empty<Contact>();
        /// <summary>Joint states in header order.</summary>
        public JointState[] Joints = Array.Empty<JointState>();
        /// <summary>Per soft body: vertex positions.</summary>
        public Vector3[][] SoftPositions = Array.Empty<Vector3[]>();
        /// <summary>Per soft body: J of each element.</summary>
        public float[][] SoftElementJ = Array.Empty<float[]>();
        /// <summary>Per soft body: ‖E‖ (Green–Lagrange strain against the rest mesh) of each element.</summary>
        public float[][] SoftElementStrain = Array.Empty<float[]>();
    }

    /// <summary>The layout version of the file.</summary>
    public int Version { get; private set; }
    /// <summary>The fixed step, s.</summary>
    public float Timestep { get; private set; }
    /// <summary>Gravity, m/s^2.</summary>
    public Vector3 Gravity { get; private set; }
    /// <summary>Bodies in header order.</summary>
    public List<Body> Bodies { get; } = new();
    /// <summary>Shapes.</summary>
    public List<Shape> Shapes { get; } = new();
    /// <summary>Joints in header order.</summary>
    public List<Joint> Joints { get; } = new();
    /// <summary>Soft bodies in header order.</summary>
    public List<SoftBody> SoftBodies { get; } = new();
    /// <summary>Whether the file ended inside a frame (a run killed while writing); that frame is left out.</summary>
    public bool Truncated { get; private set; }
    /// <summary>Frames in file order.</summary>
    public List<Frame> Frames { get; } = new();

    /// <summary>Reads a whole recording; a malformed file throws <see cref="InvalidDataException"/>.</summary>
    public static Recording Read(byte[] data)
    {
        var r = new Reader(data);
        var rec = new Recording();
        for (int i = 0; i < 4; i++)
            if (r.U8() != RecordingFormat.Magic[i]) throw new InvalidDataException("not a Fulcrum recording (the magic is not FREC)");
        rec.Version = r.U16();
        if (rec.Version != RecordingFormat.Version) throw new InvalidDataException($"recording version {rec.Version}; this build reads {RecordingFormat.Version}");
        r.U16();
        rec.Timestep = r.F32();
        rec.Gravity = r.V3();
        int n = r.Count();
        for (int i = 0; i < n; i++) rec.Bodies.Add(new Body(r.Str(), (BodyType)r.U8(), r.F32()));
        n = r.Count();
        for (int i = 0; i < n; i++) rec.Shapes.Add(ReadShape(r));
        n = r.Count();
        for (int i = 0; i < n; i++) rec.Joints.Add(new Joint(r.Str(), (JointKind)r.U8(), r.I32(), r.I32()));
        n = r.Count();
        for (int i = 0; i < n; i++)
        {
            string name = r.Str();
            int vertices = r.Count();
            int per = r.U8();
            int elements = r.Count();
            int[] el = r.Ints(elements * per);
            int[] surface = r.Ints(3 * r.Count());
            rec.SoftBodies.Add(new SoftBody(name, vertices, per, el, surface));
        }
        while (!r.AtEnd)
        {
            // A last frame cut short (the writer was killed mid-frame) is left out, not an error.
            if (data.Length - r.Position < 4 || data.Length - r.Position - 4 < BinaryPrimitives.ReadUInt32LittleEndian(data.AsSpan(r.Position)))
            {
                rec.Truncated = true;
                break;
            }
            int length = r.Count();
            int end = r.Position + length;
            rec.Frames.Add(ReadFrame(r, rec));
            if (r.Position != end) throw new InvalidDataException($"frame {rec.Frames.Count - 1}: {r.Position - end + length} bytes read, {length} declared");
        }
        return rec;
    }

    static Shape ReadShape(Reader r)
    {
        int body = r.I32();
        var type = (ShapeType)r.U8();
        Vector3 position = r.V3();
        Quaternion rotation = r.Q();
        Vector3 size = default;
        float offset = 0;
        Vector3[] vertices = Array.Empty<Vector3>();
        int[][] faces = Array.Empty<int[]>();
        int[] indices = Array.Empty<int>();
        switch (type)
        {
            case ShapeType.Sphere: size = new Vector3(r.F32(), 0, 0); break;
            case ShapeType.Box: size = r.V3(); break;
            case ShapeType.Capsule: size = new Vector3(r.F32(), r.F32(), 0); break;
            case ShapeType.Plane: size = r.V3(); offset = r.F32(); break;
            case ShapeType.ConvexHull:
                vertices = new Vector3[r.Count()];
                for (int v = 0; v < vertices.Length; v++) vertices[v] = r.V3();
                faces = new int[r.Count()][];
                for (int f = 0; f < faces.Length; f++) faces[f] = r.Ints(r.Count());
                break;
            case ShapeType.TriangleMesh:
                vertices = new Vector3[r.Count()];
                for (int v = 0; v < vertices.Length; v++) vertices[v] = r.V3();
                indices = r.Ints(r.Count());
                break;
            default: throw new InvalidDataException($"unknown shape type {(int)type}");
        }
        return new Shape(body, type, position, rotation, size, offset, vertices, faces, indices);
    }

    static Frame ReadFrame(Reader r, Recording rec)
    {
        var f = new Frame { Step = r.U32(), Time = r.F64(), Profile = new float[RecordingFormat.ProfileEntries] };
        for (int i = 0; i < f.Profile.Length; i++) f.Profile[i] = r.F32();
        f.Kinetic = r.F32();
        f.Potential = r.F32();
        f.SoftEnergy = r.F32();
        int bodies = rec.Bodies.Count;
        f.Positions = new Vector3[bodies];
        f.Rotations = new Quaternion[bodies];
        f.BodyFlags = new byte[bodies];
        for (int i = 0; i < bodies; i++)
        {
            f.Positions[i] = r.V3();
            f.Rotations[i] = r.Q();
            f.BodyFlags[i] = r.U8();
        }
        f.Contacts = new Contact[r.Count()];
        for (int i = 0; i < f.Contacts.Length; i++) f.Contacts[i] = new Contact(r.V3(), r.V3(), r.F32(), r.F32(), r.I32(), r.I32());
        f.Joints = new JointState[rec.Joints.Count];
        for (int i = 0; i < f.Joints.Length; i++)
            f.Joints[i] = new JointState(r.V3(), r.V3(), r.Q(), r.Q(), r.F32(), r.F32(), (r.U8() & RecordingFormat.JointBroken) != 0);
        f.SoftPositions = new Vector3[rec.SoftBodies.Count][];
        f.SoftElementJ = new float[rec.SoftBodies.Count][];
        f.SoftElementStrain = new float[rec.SoftBodies.Count][];
        for (int s = 0; s < rec.SoftBodies.Count; s++)
        {
            SoftBody sb = rec.SoftBodies[s];
            f.SoftPositions[s] = new Vector3[sb.VertexCount];
            for (int v = 0; v < sb.VertexCount; v++) f.SoftPositions[s][v] = r.V3();
            f.SoftElementJ[s] = new float[sb.Elements.Length / sb.VerticesPerElement];
            for (int e = 0; e < f.SoftElementJ[s].Length; e++) f.SoftElementJ[s][e] = r.F32();
            f.SoftElementStrain[s] = new float[f.SoftElementJ[s].Length];
            for (int e = 0; e < f.SoftElementStrain[s].Length; e++) f.SoftElementStrain[s][e] = r.F32();
        }
        return f;
    }

    // Little-endian cursor with bounds checks that name what ran out.
    sealed class Reader
    {
        readonly byte[] _data;
        public int Position;

        public Reader(byte[] data) => _data = data;

        public bool AtEnd => Position >= _data.Length;

        ReadOnlySpan<byte> Take(int n)
        {
            if (n < 0 || Position + n > _data.Length) throw new InvalidDataException($"recording ends early at byte {Position} (needed {n} more)");
            var s = new ReadOnlySpan<byte>(_data, Position, n);
            Position += n;
            return s;
        }

        public byte U8() => Take(1)[0];
        public ushort U16() => BinaryPrimitives.ReadUInt16LittleEndian(Take(2));
        public uint U32() => BinaryPrimitives.ReadUInt32LittleEndian(Take(4));
        public int I32() => BinaryPrimitives.ReadInt32LittleEndian(Take(4));
        public float F32() => BinaryPrimitives.ReadSingleLittleEndian(Take(4));
        public double F64() => BinaryPrimitives.ReadDoubleLittleEndian(Take(8));
        public Vector3 V3() => new(F32(), F32(), F32());
        public Quaternion Q() => new(F32(), F32(), F32(), F32());
        public string Str() => Encoding.UTF8.GetString(Take(U16()));

        // A count that must fit in what is left of the file (4 bytes per item at least is not
        // assumed; only that it is not absurd), so a corrupt count fails here, not in an allocation.
        public int Count()
        {
            uint n = U32();
            if (n > _data.Length) throw new InvalidDataException($"count {n} at byte {Position - 4} exceeds the file size");
            return (int)n;
        }

        public int[] Ints(int n)
        {
            if (n < 0 || (long)n * 4 > _data.Length - Position) throw new InvalidDataException($"recording ends early at byte {Position}");
            var a = new int[n];
            for (int i = 0; i < n; i++) a[i] = I32();
            return a;
        }
    }
}
