using System;
using System.Runtime.InteropServices;
using System.Text;

namespace Fulcrum
{
    /// <summary>
    /// Appends the binary payload of a world state (see <see cref="World.SaveState"/>): numbers
    /// little-endian, arrays of plain structs as their memory image (the struct layouts are
    /// fingerprinted in the header by <see cref="StateLayout"/>), strings as UTF-8 with a
    /// length, sections opened by a four-letter tag so that a reader that loses its place says
    /// where. Grows one buffer; nothing here runs during a step.
    /// </summary>
    internal sealed class StateWriter
    {
        byte[] _buffer = new byte[4096];
        int _length;

        /// <summary>Bytes written so far.</summary>
        public int Length => _length;

        /// <summary>The payload written so far (valid until the next write).</summary>
        public ReadOnlySpan<byte> Written => new ReadOnlySpan<byte>(_buffer, 0, _length);

        Span<byte> Take(int count)
        {
            if (_length + count > _buffer.Length)
            {
                long grown = Math.Max((long)_buffer.Length * 2, (long)_length + count);
                if (grown > int.MaxValue - 64)
                    throw new InvalidOperationException($"The world state exceeds {int.MaxValue / (1 << 20)} MiB and cannot be saved in one stream.");
                Array.Resize(ref _buffer, (int)grown);
            }
            var span = new Span<byte>(_buffer, _length, count);
            _length += count;
            return span;
        }

        /// <summary>Opens a section: the reader checks the same tag at the same place.</summary>
        public void Section(string tag) => Write(StateReader.Tag(tag));

        /// <summary>Writes one plain value as its memory image.</summary>
        public void Write<T>(T value) where T : unmanaged
        {
            Span<T> one = stackalloc T[1];
            one[0] = value;
            MemoryMarshal.AsBytes(one).CopyTo(Take(MemoryMarshal.AsBytes(one).Length));
        }

        /// <summary>Writes a count and then the first <paramref name="count"/> elements of <paramref name="array"/>.</summary>
        public void WriteArray<T>(T[] array, int count) where T : unmanaged
        {
            if ((uint)count > (uint)array.Length) throw new ArgumentOutOfRangeException(nameof(count));
            Write(count);
            ReadOnlySpan<byte> bytes = MemoryMarshal.AsBytes(new ReadOnlySpan<T>(array, 0, count));
            bytes.CopyTo(Take(bytes.Length));
        }

        /// <summary>
        /// Writes a pool: its capacity (the array's length), then its first <paramref name="count"/>
        /// elements. A restored pool has the same capacity, so it grows at the same moments.
        /// </summary>
        public void WritePool<T>(T[] array, int count) where T : unmanaged
        {
            Write(array.Length);
            WriteArray(array, count);
        }

        /// <summary>Writes a whole array (null is written as length -1).</summary>
        public void WriteArray<T>(T[]? array) where T : unmanaged
        {
            if (array == null) { Write(-1); return; }
            WriteArray(array, array.Length);
        }

        /// <summary>Writes a string (null is written as length -1).</summary>
        public void WriteString(string? s)
        {
            if (s == null) { Write(-1); return; }
            int n = Encoding.UTF8.GetByteCount(s);
            Write(n);
            Encoding.UTF8.GetBytes(s, Take(n));
        }

        /// <summary>Writes the first <paramref name="count"/> strings of <paramref name="array"/>.</summary>
        public void WriteStrings(string?[] array, int count)
        {
            Write(count);
            for (int i = 0; i < count; i++) WriteString(array[i]);
        }
    }
}
