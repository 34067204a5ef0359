using System;
using System.Buffers;

namespace Fulcrum.Collision
{
    /// <summary>
    /// A stack that starts in caller-provided (stackalloc) memory and moves to a pooled array
    /// only when it outgrows it, so tree traversals never allocate and nested traversals never
    /// share state. <see cref="Dispose"/> returns any pooled array.
    /// </summary>
    internal ref struct ScratchStack<T> where T : unmanaged
    {
        Span<T> _items;
        T[]? _rented;
        int _count;

        public ScratchStack(Span<T> initial)
        {
            _items = initial;
            _rented = null;
            _count = 0;
        }

        public readonly bool IsEmpty => _count == 0;

        public readonly int Count => _count;

        public void Push(T item)
        {
            if (_count == _items.Length) Grow();
            _items[_count++] = item;
        }

        public T Pop() => _items[--_count];

        void Grow()
        {
            T[] bigger = ArrayPool<T>.Shared.Rent(Math.Max(64, _items.Length * 2));
            _items.Slice(0, _count).CopyTo(bigger);
            if (_rented != null) ArrayPool<T>.Shared.Return(_rented);
            _rented = bigger;
            _items = bigger;
        }

        public void Dispose()
        {
            if (_rented != null) ArrayPool<T>.Shared.Return(_rented);
            _rented = null;
        }
    }
}
