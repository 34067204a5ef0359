namespace Fulcrum
{
    /// <summary>
    /// Constants of the <c>.frec</c> recording format (Documentation~/RecordingFormat.md): the
    /// magic, the version and the bits of the per-frame flag bytes. The writer
    /// (<see cref="Recorder"/>), the runner's C# reader (Samples~/Runner/Recording.cs) and the
    /// viewer's TypeScript reader (Viewer~/src/reader.ts) all follow that page.
    /// </summary>
    public static class RecordingFormat
    {
        /// <summary>The first four bytes of every recording: "FREC" in ASCII.</summary>
        public static readonly byte[] Magic = { (byte)'F', (byte)'R', (byte)'E', (byte)'C' };

        /// <summary>The layout version this build writes and reads.</summary>
        public const ushort Version = 1;

        /// <summary>Number of float32 stage times in a frame: the seven <see cref="StepStage"/>s and the total.</summary>
        public const int ProfileEntries = StepProfile.StageCount + 1;

        /// <summary>Body flag: the body is asleep (not awake) in this frame.</summary>
        public const byte BodyAsleep = 1;

        /// <summary>Body flag: the body was removed from the world after the header was written; its pose is stale.</summary>
        public const byte BodyRemoved = 2;

        /// <summary>Joint flag: the joint broke (or was removed); its frames are still written.</summary>
        public const byte JointBroken = 1;

        /// <summary>Soft-body element kind: tetrahedra (four vertex indices each).</summary>
        public const byte Tetrahedra = 4;

        /// <summary>Soft-body element kind: triangles of a shell (three vertex indices each).</summary>
        public const byte Triangles = 3;
    }
}
