using System;
using System.Collections.Generic;

namespace Fulcrum.Benchmarks.Peers
{
    /// <summary>
    /// The engines compiled into this build: Fulcrum always, BepuPhysics 2 and Jitter2 only when
    /// the build was given their assemblies (-p:BepuDir=..., -p:JitterDir=...).
    /// </summary>
    public static class PeerRoster
    {
        /// <summary>
        /// Factories for every row: Fulcrum first (the reference of the ratio column), Fulcrum with
        /// manifold reuse off and on <paramref name="threads"/> threads, then each peer compiled in
        /// (Bepu on <paramref name="threads"/> threads too; Jitter2 on one).
        /// </summary>
        public static IReadOnlyList<Func<IPeerEngine>> Engines(int threads)
        {
            var engines = new List<Func<IPeerEngine>>
            {
                () => new FulcrumPeer(),
                () => new FulcrumPeer(reuse: false),
                () => new FulcrumPeer(threads),
            };
#if PEER_BEPU
            engines.Add(() => new BepuPeer());
            engines.Add(() => new BepuPeer(threads));
#endif
#if PEER_JITTER
            engines.Add(() => new JitterPeer());
#endif
            return engines;
        }

        /// <summary>The informational version of the assembly that defines <paramref name="type"/>.</summary>
        public static string VersionOf(Type type)
        {
            var info = (System.Reflection.AssemblyInformationalVersionAttribute?)Attribute.GetCustomAttribute(
                type.Assembly, typeof(System.Reflection.AssemblyInformationalVersionAttribute));
            return info?.InformationalVersion ?? type.Assembly.GetName().Version?.ToString() ?? "?";
        }

        /// <summary>A line saying how to compile in the peers that are missing, or null when none is.</summary>
        public static string? MissingHint()
        {
            var missing = new List<string>();
#if !PEER_BEPU
            missing.Add("-p:BepuDir=DIR (a folder holding BepuPhysics.dll and BepuUtilities.dll)");
#endif
#if !PEER_JITTER
            missing.Add("-p:JitterDir=DIR (a folder holding Jitter2.dll)");
#endif
            if (missing.Count == 0) return null;
            return "not every peer is compiled in; to add the missing ones, build them from source outside this repository, then run "
                 + "dotnet run -c Release --project Samples~/Benchmarks " + string.Join(" ", missing) + " -- peers";
        }
    }
}
