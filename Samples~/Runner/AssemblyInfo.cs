using System.Runtime.CompilerServices;

// Tests check the sweep's Pareto front and plot directly.
[assembly: InternalsVisibleTo("Fulcrum.Tests")]
