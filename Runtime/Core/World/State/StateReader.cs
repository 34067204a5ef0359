using System;
using System.IO;
using System.Runtime.InteropServices;
using System.Text;

namespace Fulcrum
{
    /// <summary>
    /// Reads what <see cref="StateWriter"/> wrote, with a bounds check on every read: a state
    /// that ends early or holds a count beyond what it could contain is refused with an
    /// <see cref="InvalidDataException"/> that says what was being read and at which byte,
    /// never an index error or an allocation of garbage size.
    /// </summary>
    internal sealed class StateReader
    {
        readonly byte[] _data;
        readonly int _end;
        int _at;

        public StateReader(byte[] data, int start, int end)
        {
            _data = data;
            _at = start;
            _end = end;
        }

        /// <summary>True when every byte was read.</summary>
        public bool AtEnd => _at == _end;

        /// <summary>The four-letter tag as an int (shared with the writer).</summary>
        internal static int Tag(string tag) => tag[0] | tag[1] << 8 | tag[2] << 16 | tag[3] << 24;

        static string TagText(int tag) => new string(new[] { (char)(tag & 0xff), (char)((tag >> 8) & 0xff), (char)((tag >> 16) & 0xff), (char)((tag >> 24) & 0xff) });

        /// <summary>An error naming the byte offset.</summary>
        public InvalidDataException Error(string what) => new InvalidDataException($"World state, byte {_at}: {what}");

        ReadOnlySpan<byte> Take(int count, string what)
        {
            if (count < 0 || count > _end - _at) throw Error($"the state ends while reading {what} ({count} bytes needed, {_end - _at} left).");
            var span = new ReadOnlySpan<byte>(_data, _at, count);
            _at += count;
            return span;
        }

        /// <summary>Checks that the next section is <paramref name="tag"/>.</summary>
        public void Section(string tag)
        {
            int found = Read<int>("a section tag");
            if (found != Tag(tag)) throw Error($"expected section '{tag}', found '{TagText(found)}': the state is damaged or from another format.");
        }

        /// <summary>Reads one plain value.</summary>
        public T Read<T>(string what) where T : unmanaged
        {
            T value = default;
            Span<T> one = MemoryMarshal.CreateSpan(ref value, 1);
            Take(MemoryMarshal.AsBytes(one).Length, what).CopyTo(MemoryMarshal.AsBytes(one));
            return value;
        }

        /// <summary>Reads a count in [0, <paramref name="max"/>].</summary>
        public int Count(string what, int max)
        {
            int n = Read<int>(what);
            if (n < 0 || n > max) throw Error($"{what} is {n}, outside 0..{max}.");
            return n;
        }

        /// <summary>
        /// Reads an array written by <see cref="StateWriter.WriteArray{T}(T[], int)"/> into a new
        /// array of <paramref name="capacity"/> elements (at least the count read), so that slot
        /// arrays come back at their saved capacity.
        /// </summary>
        public T[] ReadArray<T>(string what, int capacity = 0) where T : unmanaged
        {
            int n = Read<int>(what + " length");
            int size = ElementSize<T>();
            if (n < 0 || (long)n * size > _end - _at) throw Error($"{what} claims {n} elements, more than the state holds.");
            var array = new T[Math.Max(n, capacity)];
            Take(n * size, what).CopyTo(MemoryMarshal.AsBytes(new Span<T>(array, 0, n)));
            return array;
        }

        /// <summary>
        /// Reads a per-slot array that must hold exactly <paramref name="count"/> elements into a
        /// new array of <paramref name="capacity"/> (the saved capacity of the slot arrays).
        /// </summary>
        public T[] ReadSlots<T>(string what, int count, int capacity) where T : unmanaged
        {
            int at = _at;
            int n = Read<int>(what + " length");
            _at = at;
            if (n != count) throw Error($"{what} has {n} entries, {count} expected.");
            return ReadArray<T>(what, capacity);
        }

        /// <summary>Reads what <see cref="StateWriter.WritePool{T}"/> wrote: an array at the saved capacity and the count of elements used.</summary>
        public T[] ReadPool<T>(string what, out int count) where T : unmanaged
        {
            int capacity = Count(what + " capacity", 1 << 28);
            int at = _at;
            count = Read<int>(what + " length");
            _at = at;
            if (count < 0 || count > capacity) throw Error($"{what} holds {count} elements, beyond its capacity {capacity}.");
            return ReadArray<T>(what, capacity);
        }

        /// <summary>Reads strings saved per slot: exactly <paramref name="count"/>, into an array of <paramref name="capacity"/>.</summary>
        public string?[] ReadStringSlots(string what, int count, int capacity)
        {
            int n = Read<int>(what + " count");
            if (n != count) throw Error($"{what} has {n} entries, {count} expected.");
            var array = new string?[Math.Max(n, capacity)];
            for (int i = 0; i < n; i++) array[i] = ReadString(what);
            return array;
        }

        /// <summary>Reads an array and checks that it has exactly <paramref name="length"/> elements.</summary>
        public T[] ReadArrayExactly<T>(string what, int length) where T : unmanaged
        {
            T[] a = ReadArray<T>(what);
            if (a.Length != length) throw Error($"{what} has {a.Length} elements, {length} expected.");
            return a;
        }

        /// <summary>Reads a string (or null).</summary>
        public string? ReadString(string what)
        {
            int n = Read<int>(what + " length");
            if (n == -1) return null;
            ReadOnlySpan<byte> bytes = Take(n, what);
            return Encoding.UTF8.GetString(bytes);
        }

        static int ElementSize<T>() where T : unmanaged
        {
            Span<T> one = stackalloc T[1];
            return MemoryMarshal.AsBytes(one).Length;
        }
    }
}
