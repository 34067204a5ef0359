namespace Fulcrum
{
    /// <summary>
    /// Visits the per-slot columns of a struct-of-arrays storage, each once and always in the
    /// same order, so growing (<see cref="ColumnResize"/>), saving (<see cref="ColumnWriter"/>)
    /// and loading (<see cref="ColumnReader"/>) all walk the one list the storage keeps.
    /// </summary>
    internal interface IColumnVisitor
    {
        /// <summary>A column of plain values; <paramref name="what"/> names it in load errors ("body positions").</summary>
        void Column<T>(ref T[] column, string what) where T : unmanaged;

        /// <summary>A column of strings (names).</summary>
        void Strings(ref string?[] column, string what);
    }
}
