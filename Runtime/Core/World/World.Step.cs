using System;
using System.Diagnostics;

namespace Fulcrum
{
    public sealed partial class World
    {
        static readonly double TicksToMs = 1000.0 / Stopwatch.Frequency;

        /// <summary>
        /// Advances the world by <paramref name="dt"/> seconds (a fixed step: keep the
        /// accumulator in the caller, or use <see cref="FixedStepper"/>). Runs the stages of
        /// <see cref="StepStage"/> in order, each a method of the same name in its own file
        /// (World.BroadPhase.cs ... World.SleepAndEvents.cs), between the per-step reset
        /// (<c>BeginStep</c>) and the end of step (<c>EndStep</c>); a stage with no work returns
        /// at once. Documentation~/Architecture.md walks through them.
        /// Allocates nothing once the world is warm. <paramref name="dt"/> must be in
        /// [<see cref="Limits.MinTimeStep"/>, <see cref="Limits.MaxTimeStep"/>] (1e-6 to 1 s).
        /// </summary>
        public void Step(float dt)
        {
            if (!(dt >= Limits.MinTimeStep && dt <= Limits.MaxTimeStep))
                throw new ArgumentException($"dt must be between {Limits.MinTimeStep:G} and {Limits.MaxTimeStep:G} s (Limits.MinTimeStep/MaxTimeStep), got {dt}.", nameof(dt));
            ThrowIfInStep();
            _inStep = true;
            try
            {
                _profile = default;
                long start = Stopwatch.GetTimestamp();
                long t = start;
                BeginStep(dt);

                BroadPhase(dt);
                t = Mark(StepStage.BroadPhase, t);
                NarrowPhase(dt);
                t = Mark(StepStage.NarrowPhase, t);
                Islands();
                t = Mark(StepStage.Islands, t);
                Solve(dt);
                t = Mark(StepStage.Solve, t);
                SoftBodies(dt);
                t = Mark(StepStage.SoftBodies, t);
                Continuous(dt);
                t = Mark(StepStage.Continuous, t);
                SleepAndEvents(dt);
                Mark(StepStage.SleepAndEvents, t);

                EndStep();
                _stepIndex++;
                Time += dt;
                _profile.Total = (Stopwatch.GetTimestamp() - start) * TicksToMs;
            }
            finally
            {
                _inStep = false;
            }
        }

        long Mark(StepStage stage, long since)
        {
            long now = Stopwatch.GetTimestamp();
            _profile.Add(stage, (now - since) * TicksToMs);
            return now;
        }

        // The one per-step reset: clears last step's statistics and joint breaks, remembers the
        // starting pose for render interpolation (and the starting velocities for the soft-body
        // stage) and turns kinematic targets into the velocities that reach them in this step.
        void BeginStep(float dt)
        {
            ResetStatistics();
            _jointBreakCount = 0;
            BodyStorage b = Bodies;
            bool soft = SoftBodyStage != null && SoftBodyStage.HasWork;
            for (int k = 0; k < b.ActiveCount; k++)
            {
                int i = b.Active[k];
                b.PreviousPosition[i] = b.Position[i];
                b.PreviousRotation[i] = b.Rotation[i];
                if (soft)
                {
                    b.StartLinearVelocity[i] = b.LinearVelocity[i];
                    b.StartAngularVelocity[i] = b.AngularVelocity[i];
                }
                if (b.Type[i] != BodyType.Kinematic) continue;
                if (b.HasKinematicTarget[i])
                {
                    b.LinearVelocity[i] = (b.TargetPosition[i] - b.Position[i]) / dt;
                    b.AngularVelocity[i] = Mathematics.Rotation.AngularVelocityBetween(b.Rotation[i], b.TargetRotation[i], dt);
                    b.VelocityFromTarget[i] = true;
                    b.Awake[i] = true;
                }
                else if (b.VelocityFromTarget[i])
                {
                    // A target moves the body for one step only; without a new one it stops.
                    b.LinearVelocity[i] = default;
                    b.AngularVelocity[i] = default;
                    b.VelocityFromTarget[i] = false;
                }
            }
        }

        // Snaps kinematic bodies exactly onto their targets and clears accumulated forces.
        void EndStep()
        {
            BodyStorage b = Bodies;
            for (int k = 0; k < b.ActiveCount; k++)
            {
                int i = b.Active[k];
                b.Force[i] = default;
                b.Torque[i] = default;
                if (b.HasKinematicTarget[i])
                {
                    b.Position[i] = b.TargetPosition[i];
                    b.Rotation[i] = b.TargetRotation[i];
                    b.SyncCenterFromOrigin(i);
                    b.UpdateWorldInertia(i);
                    b.HasKinematicTarget[i] = false;
                }
            }
        }
    }
}
