using System;
using System.IO;

namespace Fulcrum
{
    /// <summary>
    /// The container of a saved world state: a fixed header (magic, format version, byte order,
    /// layout fingerprints, payload length, checksum) before the payload. The checksum
    /// (64-bit FNV-1a) catches a truncated or damaged file before anything is read from it.
    /// </summary>
    internal static class StateFile
    {
        /// <summary>"FULCRUMS" in ASCII.</summary>
        const ulong Magic = 0x534D5552434C5546UL;

        /// <summary>The format version. Raise it when a section's order or meaning changes (layout changes are caught by the fingerprint).</summary>
        public const int Version = 8; // 2: the IGNR section (shape pairs that ignore each other); 3: body axis locks; 4: soft attachments no longer keep a velocity scratch; 5: soft contacts' static-friction flags; 6: the vertices whose surface triangles a rigid shape's feature met; 7: the soft vertices resting on a shape (their normal and its surface velocity); 8: the soft steps taken again with finer substeps

        const int HeaderSize = 8 + 4 + 4 + 8 + 8 + 8 + 8;

        /// <summary>The most a state may hold: 1 GiB.</summary>
        public const long MaxBytes = 1L << 30;

        /// <summary>Writes the header and the payload to <paramref name="stream"/>.</summary>
        public static void Write(Stream stream, StateWriter payload, ulong stageLayout)
        {
            var header = new StateWriter();
            header.Write(Magic);
            header.Write(Version);
            header.Write(BitConverter.IsLittleEndian ? 1 : 0);
            header.Write(StateLayout.Hash(null));
            header.Write(stageLayout);
            header.Write((long)payload.Length);
            header.Write(StateLayout.Fnv1a(payload.Written));
            stream.Write(header.Written);
            stream.Write(payload.Written);
        }

        /// <summary>
        /// Reads a whole state from <paramref name="stream"/> and checks its header and checksum;
        /// returns the bytes and where the payload lies, and the stage layout fingerprint it was
        /// written with (0 when the world had no stage).
        /// </summary>
        public static byte[] Read(Stream stream, out int start, out int end, out ulong stageLayout)
        {
            byte[] head = ReadExactly(stream, HeaderSize, "the header");
            var r = new StateReader(head, 0, head.Length);
            if (r.Read<ulong>("magic") != Magic) throw new InvalidDataException("Not a Fulcrum world state (the file does not start with FULCRUMS).");
            int version = r.Read<int>("version");
            if (version != Version) throw new InvalidDataException($"World state format {version} is not supported; this build reads format {Version}.");
            if (r.Read<int>("byte order") != (BitConverter.IsLittleEndian ? 1 : 0)) throw new InvalidDataException("The world state was written on a machine of the other byte order.");
            if (r.Read<ulong>("layout") != StateLayout.Hash(null))
                throw new InvalidDataException("The world state was written by a Fulcrum build whose internal data layout differs from this one; states load only into the build that wrote them (or one with the same layout).");
            stageLayout = r.Read<ulong>("stage layout");
            long length = r.Read<long>("payload length");
            ulong checksum = r.Read<ulong>("checksum");
            if (length < 0 || length > MaxBytes) throw new InvalidDataException($"The world state claims {length} bytes; at most {MaxBytes} are read.");
            byte[] payload = ReadExactly(stream, (int)length, "the payload");
            if (StateLayout.Fnv1a(payload) != checksum) throw new InvalidDataException("The world state is damaged: its checksum does not match its contents.");
            start = 0;
            end = payload.Length;
            return payload;
        }

        static byte[] ReadExactly(Stream stream, int count, string what)
        {
            var bytes = new byte[count];
            int got = 0;
            while (got < count)
            {
                int n = stream.Read(bytes, got, count - got);
                if (n <= 0) throw new InvalidDataException($"The world state ends early: {got} of {count} bytes of {what}.");
                got += n;
            }
            return bytes;
        }
    }
}
