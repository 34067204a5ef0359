using System;
using System.Threading;

namespace Fulcrum.Components
{
    /// <summary>
    /// A single-producer single-consumer ring of <see cref="ContactForceSample"/>: the thread
    /// that steps the world writes, one other thread (a haptics loop, say at 1 kHz) reads,
    /// without locks or allocation. When the reader falls behind and the ring is full, new
    /// samples are dropped and counted in <see cref="Dropped"/> (the reader's view stays in order).
    /// </summary>
    public sealed class HapticStream
    {
        readonly ContactForceSample[] _ring;
        long _written; // samples published (only the writer moves it)
        long _read;    // samples consumed (only the reader moves it)
        long _dropped;

        internal HapticStream(int capacity)
        {
            _ring = new ContactForceSample[Math.Max(1, capacity)];
        }

        /// <summary>How many samples the ring holds.</summary>
        public int Capacity => _ring.Length;

        /// <summary>Samples waiting to be read.</summary>
        public int Count => (int)(Volatile.Read(ref _written) - Volatile.Read(ref _read));

        /// <summary>Samples dropped because the ring was full.</summary>
        public long Dropped => Interlocked.Read(ref _dropped);

        /// <summary>Copies up to <paramref name="into"/>.Length of the oldest waiting samples out; returns how many.</summary>
        public int Read(Span<ContactForceSample> into)
        {
            long read = _read;
            long available = Volatile.Read(ref _written) - read;
            int n = (int)Math.Min(available, into.Length);
            for (int k = 0; k < n; k++) into[k] = _ring[(read + k) % _ring.Length];
            Volatile.Write(ref _read, read + n);
            return n;
        }

        internal void Write(in ContactForceSample s)
        {
            long written = _written;
            if (written - Volatile.Read(ref _read) >= _ring.Length)
            {
                Interlocked.Increment(ref _dropped);
                return;
            }
            _ring[written % _ring.Length] = s;
            Volatile.Write(ref _written, written + 1);
        }
    }
}
