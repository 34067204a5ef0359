using System;
using System.IO;
using System.Numerics;
using Fulcrum.Scenes;
using NUnit.Framework;

namespace Fulcrum.Tests.RigidScenes
{
    /// <summary>Loads the showcase scenes of Samples~/Scenes and measures what their tests assert.</summary>
    static class RigidSceneFiles
    {
        /// <summary>The Samples~/Scenes folder (soft-body meshes are found relative to it).</summary>
        public static string ScenesDirectory => ScenesDir();

        static string ScenesDir() => PackageRoot.ScenesDirectory;

        /// <summary>The scene document of Samples~/Scenes/NAME.json.</summary>
        public static SceneDocument Load(string name) => SceneFile.Load(Path.Combine(ScenesDir(), name + ".json"));

        /// <summary>The scene built on the defaults with the scene's own solver block.</summary>
        public static SceneInstance Build(string name) => SceneBuilder.Build(Load(name));

        /// <summary>Steps the scene's world <paramref name="steps"/> times at the scene's timestep.</summary>
        public static void Run(SceneInstance scene, int steps)
        {
            for (int n = 0; n < steps; n++) scene.World.Step(scene.Timestep);
        }

        /// <summary>Angle between a body's local +y and the world's +y, degrees.</summary>
        public static float TiltDeg(SceneInstance scene, string body)
        {
            Vector3 up = Vector3.Transform(Vector3.UnitY, scene.World.GetBody(scene.GetBody(body)).Rotation);
            return MathF.Acos(Math.Clamp(up.Y, -1f, 1f)) * 180f / MathF.PI;
        }

        /// <summary>The body's position.</summary>
        public static Vector3 Position(SceneInstance scene, string body) => scene.World.GetBody(scene.GetBody(body)).Position;

        /// <summary>The body's linear velocity.</summary>
        public static Vector3 Velocity(SceneInstance scene, string body) => scene.World.GetBody(scene.GetBody(body)).LinearVelocity;

        /// <summary>True when every body's position and velocity is finite.</summary>
        public static bool AllFinite(SceneInstance scene)
        {
            foreach (BodyHandle h in scene.BodyHandles)
            {
                var b = scene.World.GetBody(h);
                Vector3 p = b.Position, v = b.LinearVelocity, w = b.AngularVelocity;
                if (!(float.IsFinite(p.X + p.Y + p.Z) && float.IsFinite(v.X + v.Y + v.Z) && float.IsFinite(w.X + w.Y + w.Z))) return false;
            }
            return true;
        }
    }
}
