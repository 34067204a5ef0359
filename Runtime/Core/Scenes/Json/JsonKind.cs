namespace Fulcrum.Scenes
{
    /// <summary>The six kinds of JSON value.</summary>
    public enum JsonKind : byte
    {
        /// <summary><c>null</c>.</summary>
        Null = 0,
        /// <summary><c>true</c> or <c>false</c>.</summary>
        Bool = 1,
        /// <summary>A number, kept as its source text so that a float parses exactly once.</summary>
        Number = 2,
        /// <summary>A string.</summary>
        String = 3,
        /// <summary>An ordered list of values.</summary>
        Array = 4,
        /// <summary>An ordered list of named members.</summary>
        Object = 5,
    }
}
