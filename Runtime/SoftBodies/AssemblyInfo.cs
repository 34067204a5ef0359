using System.Runtime.CompilerServices;

// Tests check solver internals (element order, multipliers); the benchmarks build scenes directly.
[assembly: InternalsVisibleTo("Fulcrum.Tests")]
[assembly: InternalsVisibleTo("Fulcrum.Benchmarks")]
