using System;
using System.Linq;
using System.Reflection;

namespace Fulcrum.Benchmarks
{
    /// <summary>
    /// Usage: dotnet run -c Release --project Samples~/Benchmarks -- [NAME ...] [--quick]
    /// With no name, lists the benchmarks. "all" runs every one.
    /// </summary>
    public static class Program
    {
        public static int Main(string[] args)
        {
            var all = typeof(Program).Assembly.GetTypes()
                .Where(t => typeof(IBenchmark).IsAssignableFrom(t) && !t.IsAbstract && !t.IsInterface)
                .Select(t => (IBenchmark)Activator.CreateInstance(t)!)
                .OrderBy(b => b.Name, StringComparer.Ordinal)
                .ToList();
            bool quick = args.Contains("--quick");
            // A number is an option's value ("--runs 3"), never a benchmark name.
            var names = args.Where(a => !a.StartsWith("--", StringComparison.Ordinal) && !int.TryParse(a, out _)).ToList();
            if (names.Count == 0)
            {
                Console.WriteLine("Benchmarks (run with a name, or 'all'; add --quick for a smoke run):");
                foreach (var b in all) Console.WriteLine($"  {b.Name,-16} {b.Description}");
                return 0;
            }
            foreach (string name in names)
            {
                var chosen = name == "all" ? all : all.Where(b => b.Name == name).ToList();
                if (chosen.Count == 0)
                {
                    Console.Error.WriteLine($"unknown benchmark '{name}'");
                    return 2;
                }
                foreach (var b in chosen)
                {
                    Console.WriteLine($"## {b.Name}: {b.Description}");
                    Console.WriteLine($"machine: {Environment.ProcessorCount} cores, {System.Runtime.InteropServices.RuntimeInformation.OSDescription}, .NET {Environment.Version}");
                    b.Run(Console.Out, quick);
                    Console.WriteLine();
                }
            }
            return 0;
        }
    }
}
