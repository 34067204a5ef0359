using System;
using System.IO;
using System.Numerics;
using Fulcrum.Scenes;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftScenes
{
    /// <summary>
    /// A showcase scene of Samples~/Scenes loaded the way the runner loads it (file, rigid
    /// bodies, then soft bodies) and stepped at the file's own timestep.
    /// </summary>
    sealed class SoftSceneRun
    {
        public readonly SceneDocument Document;
        public readonly SceneInstance Scene;
        public readonly SoftBody Body;
        /// <summary>Every soft body of the scene, in file order (<see cref="Body"/> is the first).</summary>
        public readonly SoftBody[] All;

        SoftSceneRun(string path, Action<SceneDocument>? edit = null)
        {
            Document = SceneFile.Load(path);
            edit?.Invoke(Document);
            Scene = SceneBuilder.Build(Document);
            SoftBodyHandle[] made = SceneSoftBodyBuilder.Build(Scene);
            All = new SoftBody[made.Length];
            for (int i = 0; i < made.Length; i++) All[i] = Scene.World.GetSoftBody(made[i]);
            Body = All[0];
        }

        /// <summary>Loads Samples~/Scenes/<paramref name="name"/>.json, found above the test directory.</summary>
        public static SoftSceneRun Load(string name) => new SoftSceneRun(Path.Combine(ScenesDir(), name + ".json"));

        /// <summary>Loads a scene as <see cref="Load(string)"/> and lets <paramref name="edit"/> change the document before it is built.</summary>
        public static SoftSceneRun Load(string name, Action<SceneDocument> edit) => new SoftSceneRun(Path.Combine(ScenesDir(), name + ".json"), edit);

        public float Timestep => Document.Timestep;

        public World World => Scene.World;

        /// <summary>Whole steps in <paramref name="seconds"/>.</summary>
        public int StepsIn(float seconds) => (int)MathF.Round(seconds / Document.Timestep);

        public void Step() => Scene.World.Step(Document.Timestep);

        /// <summary>Kinetic plus strain energy of the soft body, J.</summary>
        public static float Energy(in SoftBodyStats s) => s.KineticEnergy + s.StrainEnergy;

        public static bool Finite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);

        /// <summary>True when every vertex position and velocity of the body is finite.</summary>
        public bool AllFinite()
        {
            ReadOnlySpan<Vector3> x = Body.Positions, v = Body.Velocities;
            for (int i = 0; i < x.Length; i++) if (!Finite(x[i]) || !Finite(v[i])) return false;
            return true;
        }

        static string ScenesDir() => PackageRoot.ScenesDirectory;
    }
}
