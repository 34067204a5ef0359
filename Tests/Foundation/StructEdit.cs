namespace Fulcrum.Tests
{
    /// <summary>
    /// <c>value.With((ref T s) => s.Field = x)</c>: a changed copy of a struct in one
    /// expression, where C# 10 would write <c>value with { Field = x }</c> (Unity compiles the
    /// tests as C# 9).
    /// </summary>
    static class StructEdit
    {
        public delegate void Edit<T>(ref T value);

        public static T With<T>(this T value, Edit<T> edit) where T : struct
        {
            edit(ref value);
            return value;
        }
    }
}
