namespace Fulcrum
{
    /// <summary>Reads every column it visits from a state, as <see cref="ColumnWriter"/> wrote them, into new arrays at the saved capacity.</summary>
    internal readonly struct ColumnReader : IColumnVisitor
    {
        readonly StateReader _reader;
        readonly int _count;
        readonly int _capacity;

        /// <summary>Reads columns of exactly <paramref name="count"/> slots into arrays of <paramref name="capacity"/>.</summary>
        public ColumnReader(StateReader reader, int count, int capacity)
        {
            _reader = reader;
            _count = count;
            _capacity = capacity;
        }

        public void Column<T>(ref T[] column, string what) where T : unmanaged => column = _reader.ReadSlots<T>(what, _count, _capacity);

        public void Strings(ref string?[] column, string what) => column = _reader.ReadStringSlots(what, _count, _capacity);
    }
}
