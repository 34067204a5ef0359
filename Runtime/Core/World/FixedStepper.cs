using System;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    /// <summary>
    /// Turns variable frame times into fixed physics steps: an accumulator, a cap on steps per
    /// frame (so a long frame cannot start a spiral of death; the surplus time is dropped), and
    /// the interpolation factor for rendering between the last two steps
    /// (<see cref="World.GetInterpolatedPose"/>).
    /// </summary>
    public sealed class FixedStepper
    {
        float _accumulator;

        /// <summary>Creates a stepper with the given fixed step (s) and cap on steps per frame.</summary>
        public FixedStepper(float fixedDt = 1f / 60f, int maxStepsPerFrame = 8)
        {
            Validate.Positive(fixedDt, nameof(fixedDt));
            if (maxStepsPerFrame < 1) throw new ArgumentException($"maxStepsPerFrame must be >= 1, got {maxStepsPerFrame}.", nameof(maxStepsPerFrame));
            FixedDt = fixedDt;
            MaxStepsPerFrame = maxStepsPerFrame;
        }

        /// <summary>The fixed physics step, seconds.</summary>
        public float FixedDt { get; }

        /// <summary>The most steps one frame may take.</summary>
        public int MaxStepsPerFrame { get; }

        /// <summary>Time carried over to the next frame, seconds (always &lt; <see cref="FixedDt"/> after a frame).</summary>
        public float Accumulator => _accumulator;

        /// <summary>
        /// How far the render time lies between the previous step and the last one, in [0, 1):
        /// draw each body at <c>world.GetInterpolatedPose(body, InterpolationFactor)</c>.
        /// </summary>
        public float InterpolationFactor => _accumulator / FixedDt;

        /// <summary>Time dropped so far because a frame needed more than <see cref="MaxStepsPerFrame"/> steps, seconds.</summary>
        public double DroppedTime { get; private set; }

        /// <summary>
        /// Adds a frame's time and returns how many fixed steps to take now; the caller runs its
        /// own fixed-update logic and <see cref="World.Step"/> that many times.
        /// </summary>
        public int Consume(float frameDt)
        {
            Validate.NonNegative(frameDt, nameof(frameDt));
            _accumulator += frameDt;
            int steps = (int)MathF.Floor(_accumulator / FixedDt);
            if (steps > MaxStepsPerFrame)
            {
                DroppedTime += (steps - MaxStepsPerFrame) * (double)FixedDt;
                steps = MaxStepsPerFrame;
                _accumulator = MathF.Min(_accumulator - steps * FixedDt, FixedDt * 0.999f);
                return steps;
            }
            _accumulator -= steps * FixedDt;
            if (_accumulator < 0) _accumulator = 0;
            return steps;
        }

        /// <summary>Adds a frame's time and steps <paramref name="world"/> as often as it calls for; returns the number of steps.</summary>
        public int Advance(World world, float frameDt)
        {
            int steps = Consume(frameDt);
            for (int k = 0; k < steps; k++) world.Step(FixedDt);
            return steps;
        }

        /// <summary>Forgets accumulated time.</summary>
        public void Reset() => _accumulator = 0;
    }
}
