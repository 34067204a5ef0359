using System;
using System.Buffers.Binary;
using System.IO;
using System.Numerics;
using System.Text;

namespace Fulcrum
{
    /// <summary>
    /// The little-endian byte buffer a <see cref="Recorder"/> builds the header and each frame
    /// in, shared with the stages of other assemblies (<see cref="IRecordingStage"/>) that write
    /// their own blocks. It grows to the largest frame and is then reused, so writing a frame
    /// allocates nothing once warm. Floats go through their bit patterns
    /// (<see cref="BitConverter.SingleToInt32Bits"/>) because netstandard2.1 has no
    /// BinaryPrimitives float writers.
    /// </summary>
    internal sealed class RecordingWriter
    {
        byte[] _buffer = new byte[1 << 16];

        /// <summary>Bytes in the buffer.</summary>
        public int Length;

        /// <summary>Hands the buffer to <paramref name="stream"/> in one write and empties it; returns the bytes written.</summary>
        public int FlushTo(Stream stream)
        {
            int n = Length;
            stream.Write(_buffer, 0, n);
            Length = 0;
            return n;
        }

        /// <summary>Overwrites the u32 at byte <paramref name="at"/> (a length prefix known only later).</summary>
        public void PatchU32(int at, int v) => BinaryPrimitives.WriteUInt32LittleEndian(_buffer.AsSpan(at, 4), (uint)v);

        Span<byte> Take(int bytes)
        {
            if (Length + bytes > _buffer.Length) Array.Resize(ref _buffer, Math.Max(_buffer.Length * 2, Length + bytes));
            Span<byte> span = _buffer.AsSpan(Length, bytes);
            Length += bytes;
            return span;
        }

        public void U8(byte v) => Take(1)[0] = v;
        public void U16(ushort v) => BinaryPrimitives.WriteUInt16LittleEndian(Take(2), v);
        public void U32(int v) => BinaryPrimitives.WriteUInt32LittleEndian(Take(4), (uint)v);
        public void I32(int v) => BinaryPrimitives.WriteInt32LittleEndian(Take(4), v);
        public void F32(float v) => BinaryPrimitives.WriteInt32LittleEndian(Take(4), BitConverter.SingleToInt32Bits(v));
        public void F64(double v) => BinaryPrimitives.WriteInt64LittleEndian(Take(8), BitConverter.DoubleToInt64Bits(v));

        public void V3(Vector3 v)
        {
            Span<byte> s = Take(12);
            BinaryPrimitives.WriteInt32LittleEndian(s, BitConverter.SingleToInt32Bits(v.X));
            BinaryPrimitives.WriteInt32LittleEndian(s.Slice(4), BitConverter.SingleToInt32Bits(v.Y));
            BinaryPrimitives.WriteInt32LittleEndian(s.Slice(8), BitConverter.SingleToInt32Bits(v.Z));
        }

        public void Q(Quaternion q)
        {
            Span<byte> s = Take(16);
            BinaryPrimitives.WriteInt32LittleEndian(s, BitConverter.SingleToInt32Bits(q.X));
            BinaryPrimitives.WriteInt32LittleEndian(s.Slice(4), BitConverter.SingleToInt32Bits(q.Y));
            BinaryPrimitives.WriteInt32LittleEndian(s.Slice(8), BitConverter.SingleToInt32Bits(q.Z));
            BinaryPrimitives.WriteInt32LittleEndian(s.Slice(12), BitConverter.SingleToInt32Bits(q.W));
        }

        /// <summary>
        /// UTF-8 with a u16 byte length (header only: it allocates). Names are capped at 256
        /// characters by the scene reader, so the cap here only guards hand-made worlds.
        /// </summary>
        public void Str(string s)
        {
            byte[] bytes = Encoding.UTF8.GetBytes(s.Length > 1024 ? s.Substring(0, 1024) : s);
            U16((ushort)bytes.Length);
            bytes.CopyTo(Take(bytes.Length));
        }
    }
}
