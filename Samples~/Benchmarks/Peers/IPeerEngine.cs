using System;
using System.Numerics;

namespace Fulcrum.Benchmarks.Peers
{
    /// <summary>One physics engine driven through the same small surface: build a scene, step, read poses.</summary>
    public interface IPeerEngine : IDisposable
    {
        /// <summary>Name printed in the table (with the version where known).</summary>
        string Name { get; }

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
