using System.Runtime.CompilerServices;

// The other Fulcrum assemblies read body and shape storage directly (same package, one
// engine); tests and tools check internal invariants.
[assembly: InternalsVisibleTo("Fulcrum.SoftBodies")]
[assembly: InternalsVisibleTo("Fulcrum.Components")]
[assembly: InternalsVisibleTo("Fulcrum.Tests")]
[assembly: InternalsVisibleTo("Fulcrum.Benchmarks")]
[assembly: InternalsVisibleTo("fulcrum")]
