using System;
using Fulcrum;
using Fulcrum.Mathematics;
using Fulcrum.Scenes;
using Fulcrum.SoftBodies;
using UnityEngine;

namespace FulcrumScenes
{
    /// <summary>
    /// Plays one of the sample's scene files inside Unity: add it to a GameObject, drag a
    /// scene (any .json file of this folder, imported as a TextAsset) onto
    /// <see cref="sceneFile"/> and press Play. The scene is built headless (rigid bodies,
    /// joints and generated soft bodies), stepped from FixedUpdate at the scene's own time step
    /// and drawn with gizmos: each rigid shape's bounding box and each soft body's vertices.
    /// Scenes whose soft bodies read mesh files (tetgen, obj) play without those soft bodies,
    /// with a warning in the Console: a TextAsset has no folder to resolve the files against.
    /// </summary>
    public sealed class ScenePlayer : MonoBehaviour
    {
        /// <summary>The scene file to play.</summary>
        public TextAsset sceneFile;

        SceneInstance _scene;
        SoftBodyHandle[] _softBodies = Array.Empty<SoftBodyHandle>();
        float _accumulator;

        void OnEnable()
        {
            if (sceneFile == null) { Debug.LogWarning("ScenePlayer: no scene file assigned"); return; }
            try
            {
                _scene = SceneBuilder.Build(SceneFile.Parse(sceneFile.text));
            }
            catch (SceneException e)
            {
                Debug.LogError($"ScenePlayer: {sceneFile.name}: {e.Message}");
                return;
            }
            try
            {
                _softBodies = SceneSoftBodyBuilder.Build(_scene);
            }
            catch (SceneException e)
            {
                Debug.LogWarning($"ScenePlayer: {sceneFile.name}: soft bodies left out: {e.Message}");
            }
            Debug.Log($"ScenePlayer: {sceneFile.name}: {_scene.World.BodyCount} bodies, {_softBodies.Length} soft bodies, step {_scene.Timestep} s");
        }

        void OnDisable()
        {
            _scene = null;
            _softBodies = Array.Empty<SoftBodyHandle>();
        }

        // The scene's step need not equal Unity's: step it as many times as fits in Unity's.
        void FixedUpdate()
        {
            if (_scene == null) return;
            _accumulator += Time.fixedDeltaTime;
            while (_accumulator >= _scene.Timestep)
            {
                _scene.World.Step(_scene.Timestep);
                _accumulator -= _scene.Timestep;
            }
        }

        void OnDrawGizmos()
        {
            if (_scene == null) return;
            World world = _scene.World;
            Span<ShapeHandle> shapes = stackalloc ShapeHandle[16];
            Gizmos.color = Color.red;
            for (int i = 0; i < _scene.BodyHandles.Count; i++)
            {
                int count = Math.Min(world.GetShapes(_scene.BodyHandles[i], shapes), shapes.Length);
                for (int s = 0; s < count; s++)
                {
                    Aabb box = world.GetShapeAabb(shapes[s]);
                    System.Numerics.Vector3 c = (box.Min + box.Max) * 0.5f, e = box.Max - box.Min;
                    Gizmos.DrawWireCube(new Vector3(c.X, c.Y, c.Z), new Vector3(e.X, e.Y, e.Z));
                }
            }
            foreach (SoftBodyHandle handle in _softBodies)
            {
                ReadOnlySpan<System.Numerics.Vector3> x = world.GetSoftBody(handle).Positions;
                for (int v = 0; v < x.Length; v++) Gizmos.DrawSphere(new Vector3(x[v].X, x[v].Y, x[v].Z), 0.02f);
            }
        }
    }
}
