using System.Collections.Generic;
using System.Runtime.CompilerServices;

namespace Fulcrum.Tests.State
{
    /// <summary>
    /// Object identity as an equality comparer: .NET 5's ReferenceEqualityComparer, which
    /// .NET Standard 2.1 (Unity's test compile) lacks.
    /// </summary>
    sealed class ReferenceComparer : IEqualityComparer<object>
    {
        public static readonly ReferenceComparer Instance = new ReferenceComparer();

        public new bool Equals(object? a, object? b) => ReferenceEquals(a, b);

        public int GetHashCode(object o) => RuntimeHelpers.GetHashCode(o);
    }
}
