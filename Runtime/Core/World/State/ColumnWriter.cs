namespace Fulcrum
{
    /// <summary>Writes the used slots of every column it visits to a state.</summary>
    internal readonly struct ColumnWriter : IColumnVisitor
    {
        readonly StateWriter _writer;
        readonly int _count;

        /// <summary>Writes the first <paramref name="count"/> slots (<see cref="SlotStorage.SlotCount"/>) of each column.</summary>
        public ColumnWriter(StateWriter writer, int count)
        {
            _writer = writer;
            _count = count;
        }

        public void Column<T>(ref T[] column, string what) where T : unmanaged => _writer.WriteArray(column, _count);

        public void Strings(ref string?[] column, string what) => _writer.WriteStrings(column, _count);
    }
}
