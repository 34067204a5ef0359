using System;
using System.Diagnostics;
using System.IO;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Dynamics;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    /// <summary>
    /// Writes a world to a <c>.frec</c> recording for the browser viewer
    /// (Documentation~/RecordingFormat.md): the constructor writes the header (bodies, shapes
    /// with their geometry, joints, soft-body meshes) and <see cref="Record(long)"/> appends one
    /// frame (poses, sleeping flags, contact points, joint frames and errors, soft-body
    /// vertices, element J and strain, the step's stage times, energies).
    /// <para>
    /// Use: create it between steps, call <see cref="Record(long)"/> after each step you want
    /// (and once before the first for the starting state), dispose it at the end. The
    /// components' <c>PhysicsScene.StartRecording</c> and the <c>PhysicsBridge</c> do this for
    /// you, on the thread that steps. Recording only reads the world: a run gives bit-identical
    /// results with and without it.
    /// </para>
    /// <para>
    /// What exists when the recorder is created is what is recorded: bodies, joints and soft
    /// bodies created later are not in the header and are left out of the frames (a removed
    /// body is flagged, a removed joint is written as broken). Contacts involving such bodies
    /// carry body index -1. Contacts of sleeping islands are left out unless
    /// <see cref="SleepingContacts"/> is set.
    /// </para>
    /// <para>
    /// Cost: a frame is built in one reusable byte buffer and handed to the stream in one write,
    /// so once the buffer has grown to the largest frame, recording allocates nothing per step
    /// (given a stream that does not allocate per write, such as a <see cref="FileStream"/>).
    /// With <see cref="Enabled"/> false, <see cref="Record(long)"/> returns at once and
    /// allocates nothing either.
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
        readonly IRecordingBlock? _soft;  // the soft-body stage's blocks, null without one
        readonly RecordingWriter _writer = new RecordingWriter();
        long _ticks;
        bool _disposed;

        /// <summary>
        /// Writes the header of <paramref name="world"/> to <paramref name="stream"/>.
        /// <paramref name="bodyNames"/> (optional) names bodies that have no name of their own
        /// in the world. Nothing is written when an argument is bad.
        /// </summary>
        /// <param name="world">The world to record; call between steps, on the thread that steps it.</param>
        /// <param name="timestep">The fixed step the caller will use, s (written to the header; the world does not keep it).</param>
        /// <param name="stream">Where to write (a file stream, a socket's stream, or memory in tests).</param>
        /// <param name="ownsStream">Whether <see cref="Dispose"/> closes <paramref name="stream"/>.</param>
        /// <param name="bodyNames">Names for unnamed bodies, or null.</param>
        public Recorder(World world, float timestep, Stream stream, bool ownsStream = true, Func<BodyHandle, string?>? bodyNames = null)
        {
            _world = world ?? throw new ArgumentNullException(nameof(world));
            _stream = stream ?? throw new ArgumentNullException(nameof(stream));
            if (!stream.CanWrite) throw new ArgumentException("Recorder: the stream is not writable.", nameof(stream));
            if (!(timestep > 0) || float.IsInfinity(timestep)) throw new ArgumentOutOfRangeException(nameof(timestep), timestep, "Recorder: the timestep must be finite and > 0.");
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

            _soft = (world.SoftBodyStage as IRecordingStage)?.BeginRecording(world);

            WriteHeader(timestep, bodyNames);
            Flush();
        }

        /// <summary>Whether <see cref="Record(long)"/> writes frames; false makes it return at once (default true).</summary>
        public bool Enabled { get; set; } = true;

        /// <summary>
        /// Whether frames also list the contacts of sleeping islands, with the impulses of the
        /// last step that solved them, so that a settled stack still shows what holds it up.
        /// Off by default: they cost 40 bytes per point in every frame, and a settled pile is
        /// mostly contacts (300 steps of the 56-box pyramid: 17.3 KiB per frame with them,
        /// 3.3 KiB without; the 211-box pyramid-20: 98.3 against 20.8 KiB). Off, a frame lists
        /// the contacts the step solved (pairs with an awake body).
        /// </summary>
        public bool SleepingContacts { get; set; }

        /// <summary>Frames written so far.</summary>
        public int FrameCount { get; private set; }

        /// <summary>Bytes written so far, header included.</summary>
        public long BytesWritten { get; private set; }

        /// <summary>Time spent in <see cref="Record(long)"/> writing frames, ms (what recording costs a run).</summary>
        public double RecordMilliseconds => _ticks * 1000.0 / Stopwatch.Frequency;

        /// <summary>
        /// Appends one frame: the world's state now, tagged with <paramref name="step"/> (0 for
        /// the state before the first step). Call between steps. Does nothing when
        /// <see cref="Enabled"/> is false.
        /// </summary>
        public void Record(long step)
        {
            if (!Enabled) return;
            if (_disposed) throw new ObjectDisposedException(nameof(Recorder));
            long start = Stopwatch.GetTimestamp();
            _writer.Length = 0;
            _writer.U32(0); // the frame's byte length goes here once it is known
            WriteFrame(step);
            _writer.PatchU32(0, _writer.Length - 4);
            Flush();
            FrameCount++;
            _ticks += Stopwatch.GetTimestamp() - start;
        }

        /// <summary>Appends one frame tagged with the world's <see cref="World.StepIndex"/>.</summary>
        public void Record() => Record(_world.StepIndex);

        /// <summary>Flushes and, if the recorder owns it, closes the stream. Later <see cref="Record(long)"/> calls throw.</summary>
        public void Dispose()
        {
            if (_disposed) return;
            _disposed = true;
            try { _stream.Flush(); }
            finally { if (_ownsStream) _stream.Dispose(); }
        }

        void WriteHeader(float timestep, Func<BodyHandle, string?>? bodyNames)
        {
            World w = _world;
            BodyStorage b = w.Bodies;
            ShapeStorage s = w.Shapes;
            RecordingWriter o = _writer;
            o.Length = 0;
            for (int i = 0; i < 4; i++) o.U8(RecordingFormat.Magic[i]);
            o.U16(RecordingFormat.Version);
            o.U16(0);
            o.F32(timestep);
            o.V3(w.Gravity);

            o.U32(_bodySlots.Length);
            foreach (int i in _bodySlots)
            {
                string? name = b.Name[i] ?? bodyNames?.Invoke(new BodyHandle(i, b.Generation[i], w.Id));
                o.Str(name ?? "#" + i);
                o.U8((byte)b.Type[i]);
                o.F32(b.Type[i] == BodyType.Dynamic ? b.Mass[i] : 0);
            }

            int shapeCount = 0;
            foreach (int i in _bodySlots)
                for (int sh = b.FirstShape[i]; sh >= 0; sh = s.NextInBody[sh]) shapeCount++;
            o.U32(shapeCount);
            for (int k = 0; k < _bodySlots.Length; k++)
                for (int sh = b.FirstShape[_bodySlots[k]]; sh >= 0; sh = s.NextInBody[sh])
                    WriteShape(k, s.Geometry[sh], s.LocalPose[sh]);

            JointStorage j = w.Joints;
            o.U32(_jointSlots.Length);
            foreach (int slot in _jointSlots)
            {
                ref JointData d = ref j.Data[slot];
                o.Str(j.Name[slot] ?? "joint" + slot);
                o.U8((byte)d.Kind);
                o.I32(BodyIndex(d.BodyA));
                o.I32(BodyIndex(d.BodyB));
            }

            if (_soft != null) _soft.WriteHeader(o);
            else o.U32(0);
        }

        void WriteShape(int body, in ShapeGeometry g, in Pose local)
        {
            RecordingWriter o = _writer;
            o.U32(body);
            o.U8((byte)g.Type);
            o.V3(local.Position);
            o.Q(local.Rotation);
            switch (g.Type)
            {
                case ShapeType.Sphere:
                    o.F32(g.Radius);
                    break;
                case ShapeType.Box:
                    o.V3(g.HalfExtents);
                    break;
                case ShapeType.Capsule:
                    o.F32(g.Radius);
                    o.F32(g.HalfHeight);
                    break;
                case ShapeType.ConvexHull:
                {
                    var hull = (ConvexHull)g.Data!;
                    o.U32(hull.VertexCount);
                    for (int v = 0; v < hull.VertexCount; v++) o.V3(hull.GetVertex(v));
                    o.U32(hull.FaceCount);
                    for (int f = 0; f < hull.FaceCount; f++)
                    {
                        ReadOnlySpan<int> face = hull.GetFace(f);
                        o.U32(face.Length);
                        foreach (int v in face) o.U32(v);
                    }
                    break;
                }
                case ShapeType.Plane:
                    o.V3(g.Normal);
                    o.F32(g.Offset);
                    break;
                case ShapeType.TriangleMesh:
                {
                    var mesh = (TriangleMesh)g.Data!;
                    o.U32(mesh.Vertices.Length);
                    foreach (Vector3 v in mesh.Vertices) o.V3(v);
                    o.U32(mesh.Indices.Length);
                    foreach (int i in mesh.Indices) o.U32(i);
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
            RecordingWriter o = _writer;
            o.U32((int)Math.Min(Math.Max(step, 0), uint.MaxValue));
            o.F64(w.Time);
            StepProfile p = w.LastStepProfile;
            for (int stage = 0; stage < StepProfile.StageCount; stage++) o.F32((float)p[(StepStage)stage]);
            o.F32((float)p.Total);
            o.F32(RigidEnergy.Kinetic(w));
            o.F32(RigidEnergy.Potential(w));
            o.F32(_soft != null ? _soft.Energy() : 0f);

            for (int k = 0; k < _bodySlots.Length; k++)
            {
                int i = _bodySlots[k];
                bool live = b.Generation[i] == _bodyGenerations[k] && b.ActiveIndex[i] >= 0;
                o.V3(b.Position[i]);
                o.Q(b.Rotation[i]);
                byte flags = 0;
                if (!live) flags |= RecordingFormat.BodyRemoved;
                else if (b.Type[i] != BodyType.Static && !b.Awake[i]) flags |= RecordingFormat.BodyAsleep;
                o.U8(flags);
            }

            WriteContacts();

            JointStorage j = w.Joints;
            for (int k = 0; k < _jointSlots.Length; k++)
            {
                int slot = _jointSlots[k];
                ref JointData d = ref j.Data[slot];
                bool live = j.Generation[slot] == _jointGenerations[k] && j.ActiveIndex[slot] >= 0;
                WorldFrame(d.BodyA, d.LocalAnchorA, d.LocalFrameA, out Vector3 anchorA, out Quaternion frameA);
                WorldFrame(d.BodyB, d.LocalAnchorB, d.LocalFrameB, out Vector3 anchorB, out Quaternion frameB);
                o.V3(anchorA);
                o.V3(anchorB);
                o.Q(frameA);
                o.Q(frameB);
                o.F32(d.Error);
                o.F32(d.Stress);
                o.U8(!live || d.Broken ? RecordingFormat.JointBroken : (byte)0);
            }

            _soft?.WriteFrame(o);
        }

        // The step's manifolds (the solver's list: pairs with an awake body), then, with
        // SleepingContacts, those of pairs the narrow phase skipped because both bodies sleep:
        // their manifolds stay in the contact graph with the impulses of the last step that
        // solved them, so reading them costs a pass over the contacts and changes nothing.
        void WriteContacts()
        {
            RecordingWriter o = _writer;
            ContactSet contacts = _world.Contacts;
            ContactGraph g = _world.ContactGraph;
            int points = 0, sleeping = SleepingContacts ? g.DenseCount : 0;
            for (int m = 0; m < contacts.ManifoldCount; m++) points += contacts[m].PointCount;
            for (int k = 0; k < sleeping; k++)
            {
                ref Contact ct = ref g.Contacts[g.Dense[k]];
                if (!IsSleeping(ct)) continue;
                for (int m = ct.FirstManifold; m >= 0; m = g.ManifoldNext[m]) points += g.Manifolds[m].PointCount;
            }
            o.U32(points);
            for (int m = 0; m < contacts.ManifoldCount; m++) WriteManifold(ref contacts[m]);
            for (int k = 0; k < sleeping; k++)
            {
                ref Contact ct = ref g.Contacts[g.Dense[k]];
                if (!IsSleeping(ct)) continue;
                for (int m = ct.FirstManifold; m >= 0; m = g.ManifoldNext[m]) WriteManifold(ref g.Manifolds[m]);
            }
        }

        // Not run by this step's narrow phase (so not in the step's list), not a sensor, and
        // both bodies asleep or static now.
        bool IsSleeping(in Contact ct) =>
            (ct.Flags & (ContactFlags.Updated | ContactFlags.Sensor)) == 0 && ct.FirstManifold >= 0 &&
            !_world.Bodies.Awake[ct.BodyA] && !_world.Bodies.Awake[ct.BodyB];

        void WriteManifold(ref ContactManifold manifold)
        {
            RecordingWriter o = _writer;
            for (int k = 0; k < manifold.PointCount; k++)
            {
                ref ContactPoint cp = ref ContactManifold.Point(ref manifold, k);
                o.V3(cp.Position);
                o.V3(manifold.Normal);
                o.F32(cp.NormalImpulse);
                o.F32(cp.Separation);
                o.I32(BodyIndex(manifold.BodyA));
                o.I32(BodyIndex(manifold.BodyB));
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

        void Flush() => BytesWritten += _writer.FlushTo(_stream);
    }
}
