using System;
using System.Numerics;

namespace Fulcrum.Benchmarks.Peers
{
    /// <summary>One physics engine driven through the same small surface: build a scene, step, read poses.</summary>
    public interface IPeerEngine : IDisposable
    {
        /// <summary>Row label printed in the table: the engine and any setting that differs from the matched one.</summary>
        string Name { get; }

        /// <summary>Threads a step may use (1: the calling thread only).</summary>
        int Threads { get; }

        /// <summary>The engine assembly's informational version (with the source commit where the build recorded one).</summary>
        string Version { get; }

        /// <summary>Creates the ground and the boxes of <paramref name="scene"/> with <paramref name="settings"/>.</summary>
        void Build(PeerScene scene, PeerSettings settings);

        /// <summary>Advances one fixed step of <paramref name="dt"/> seconds on the calling thread.</summary>
        void Step(float dt);

        /// <summary>Pose of box <paramref name="box"/> (index into <see cref="PeerScene.Boxes"/>).</summary>
        void ReadPose(int box, out Vector3 position, out Quaternion rotation);
    }
}
