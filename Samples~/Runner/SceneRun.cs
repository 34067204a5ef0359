using System;
using System.Collections.Generic;
using System.Numerics;
using Fulcrum.Scenes;

namespace Fulcrum.Runner;

/// <summary>Steps a built scene a number of times, measuring as it goes and feeding a trace.</summary>
static class SceneRun
{
    /// <param name="scene">The built scene.</param>
    /// <param name="steps">Steps to take.</param>
    /// <param name="dt">The fixed step, s.</param>
    /// <param name="soft">The soft bodies' monitor, or null.</param>
    /// <param name="trace">Where to record, or null.</param>
    /// <param name="every">Record every K-th step (and the last one).</param>
    /// <param name="afterStep">Called after each step with the step number (1-based).</param>
    public static RunResult Run(SceneInstance scene, int steps, float dt, ISoftBodyMonitor? soft = null,
        TraceWriter? trace = null, int every = 1, Action<int>? afterStep = null)
    {
        World world = scene.World;
        var ms = new double[steps];
        float maxPenetration = 0, maxJointError = 0, volumeError = 0, minJ = float.PositiveInfinity;
        float energyStart = RigidEnergy.Kinetic(world) + RigidEnergy.Potential(world);
        Ballistic? ballistic = Ballistic.Of(scene);
        trace?.Record(0, scene, soft, 0);
        Sample(soft, ref volumeError, ref minJ);
        for (int n = 1; n <= steps; n++)
        {
            world.Step(dt);
            ms[n - 1] = world.LastStepProfile.Total;
            maxPenetration = MathF.Max(maxPenetration, world.MaxPenetration);
            maxJointError = MathF.Max(maxJointError, world.MaxJointError);
            ballistic?.Measure(world, n * (double)dt);
            Sample(soft, ref volumeError, ref minJ);
            if (trace != null && (n % every == 0 || n == steps)) trace.Record(n, scene, soft, (float)ms[n - 1]);
            afterStep?.Invoke(n);
        }
        return new RunResult
        {
            Steps = steps,
            StepMs = ms,
            MaxPenetration = maxPenetration,
            MaxJointError = scene.JointHandles.Count > 0 ? maxJointError : null,
            EnergyStart = energyStart,
            EnergyEnd = RigidEnergy.Kinetic(world) + RigidEnergy.Potential(world),
            VolumeError = soft != null ? volumeError : null,
            MinJ = soft != null ? minJ : null,
            ClosedFormError = ballistic?.MaxError,
        };
    }

    static void Sample(ISoftBodyMonitor? soft, ref float volumeError, ref float minJ)
    {
        if (soft == null) return;
        for (int s = 0; s < soft.Count; s++)
        {
            SoftBodySample x = soft.Sample(s);
            volumeError = MathF.Max(volumeError, MathF.Abs(x.VolumeRatio - 1));
            minJ = MathF.Min(minJ, x.MinJ);
        }
    }

    /// <summary>
    /// The closed-form check of a scene where every body flies free (no static or kinematic
    /// bodies, joints or soft bodies): each centre of mass should follow c0 + v0 t + g t^2 / 2.
    /// Semi-implicit Euler lands g t dt / 2 away from it (x_n = x0 + v0 t + g t (t + dt) / 2),
    /// so the error grows linearly in time and dt; anything more is a bug or a collision.
    /// </summary>
    sealed class Ballistic
    {
        readonly List<(BodyHandle body, Vector3 c0, Vector3 v0)> _bodies = new();
        Vector3 _g;
        public float MaxError { get; private set; }

        public static Ballistic? Of(SceneInstance scene)
        {
            if (scene.Joints.Count > 0 || scene.SoftBodies.Count > 0 || scene.BodyHandles.Count == 0) return null;
            var b = new Ballistic { _g = scene.World.Gravity };
            foreach (BodyHandle h in scene.BodyHandles)
            {
                BodyRef body = scene.World.GetBody(h);
                if (body.Type != BodyType.Dynamic) return null;
                b._bodies.Add((h, body.CenterOfMass, body.LinearVelocity));
            }
            return b;
        }

        public void Measure(World world, double t)
        {
            foreach ((BodyHandle h, Vector3 c0, Vector3 v0) in _bodies)
            {
                Vector3 expected = c0 + v0 * (float)t + _g * (float)(0.5 * t * t);
                MaxError = MathF.Max(MaxError, Vector3.Distance(world.GetBody(h).CenterOfMass, expected));
            }
        }
    }
}
