using System.IO;

namespace Fulcrum.Benchmarks
{
    /// <summary>
    /// One benchmark: a named table of measurements. Program finds every implementation by
    /// reflection, so a new benchmark is one new file.
    /// </summary>
    public interface IBenchmark
    {
        /// <summary>Command-line name, e.g. "broadphase".</summary>
        string Name { get; }

        /// <summary>One line saying what it measures.</summary>
        string Description { get; }

        /// <summary>Runs and prints a table to <paramref name="output"/>. <paramref name="quick"/> shrinks sizes for a smoke run.</summary>
        void Run(TextWriter output, bool quick);
    }
}
