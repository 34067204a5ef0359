using System;

namespace Fulcrum
{
    /// <summary>Resizes every column it visits to a new slot capacity (the allocator grew).</summary>
    internal readonly struct ColumnResize : IColumnVisitor
    {
        readonly int _capacity;

        public ColumnResize(int capacity) => _capacity = capacity;

        public void Column<T>(ref T[] column, string what) where T : unmanaged => Array.Resize(ref column, _capacity);

        public void Strings(ref string?[] column, string what) => Array.Resize(ref column, _capacity);
    }
}
