using System;

namespace Fulcrum.Components
{
    /// <summary>
    /// The component that owns each world handle of one kind (a collider per shape, a joint
    /// component per joint), by the handle's slot. An entry holds the generation it was set
    /// for, so a handle to a slot reused since finds nothing; entries are only overwritten,
    /// so a removed handle still finds its owner until the slot is reused.
    /// </summary>
    internal sealed class HandleOwners<T> where T : class
    {
        T?[] _owner = Array.Empty<T?>();
        int[] _generation = Array.Empty<int>();

        /// <summary>Records <paramref name="owner"/> as the owner of <paramref name="handle"/>.</summary>
        public void Set(HandleId handle, T owner)
        {
            if (handle.Index >= _owner.Length)
            {
                int n = Math.Max(handle.Index + 1, Math.Max(16, _owner.Length * 2));
                Array.Resize(ref _owner, n);
                Array.Resize(ref _generation, n);
            }
            _owner[handle.Index] = owner;
            _generation[handle.Index] = handle.Generation;
        }

        /// <summary>The owner of <paramref name="handle"/>; null for none, a slot never set, or one set for another generation.</summary>
        public T? Get(HandleId handle)
        {
            if (handle.IsNone || (uint)handle.Index >= (uint)_owner.Length) return null;
            return _generation[handle.Index] == handle.Generation ? _owner[handle.Index] : null;
        }
    }
}
