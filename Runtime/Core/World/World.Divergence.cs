using System;
using System.Numerics;

namespace Fulcrum
{
    public sealed partial class World
    {
        /// <summary>
        /// Raised (on the stepping thread, at the end of the step) for each body a step could not
        /// keep finite or inside the world bounds. The world has already put the body back at its
        /// pose from the start of that step and stopped it, so nothing else turns NaN through
        /// contacts or joints. No delegate is called (and nothing allocated) while nothing diverges.
        /// </summary>
        public event Action<Divergence>? Diverged;

        /// <summary>Bodies that diverged since the world was created (see <see cref="Diverged"/>).</summary>
        public int DivergenceCount { get; private set; }

        /// <summary>The latest divergence; meaningful when <see cref="DivergenceCount"/> &gt; 0.</summary>
        public Divergence LastDivergence { get; private set; }

        // After the last stage that moves bodies: one pass over the active bodies. A body whose
        // state is not finite, or that left the bounds, is put back at the step's starting pose
        // (BeginStep stored it for interpolation) with no velocity, and reported.
        void CheckDivergence()
        {
            BodyStorage b = Bodies;
            float bound = Limits.MaxPosition;
            for (int k = 0; k < b.ActiveCount; k++)
            {
                int i = b.Active[k];
                Vector3 p = b.Position[i], v = b.LinearVelocity[i], w = b.AngularVelocity[i];
                Quaternion q = b.Rotation[i];
                // One sum carries any NaN or infinity of its terms.
                float sum = p.X + p.Y + p.Z + v.X + v.Y + v.Z + w.X + w.Y + w.Z + q.X + q.Y + q.Z + q.W;
                DivergenceKind kind;
                if (!float.IsFinite(sum)) kind = DivergenceKind.NonFinite;
                else if (MathF.Abs(p.X) > bound || MathF.Abs(p.Y) > bound || MathF.Abs(p.Z) > bound) kind = DivergenceKind.OutOfBounds;
                else continue;
                b.Position[i] = b.PreviousPosition[i];
                b.Rotation[i] = b.PreviousRotation[i];
                b.LinearVelocity[i] = default;
                b.AngularVelocity[i] = default;
                b.SyncCenterFromOrigin(i);
                b.UpdateWorldInertia(i);
                var d = new Divergence(new BodyHandle(i, b.Generation[i], Id), _stepIndex, kind);
                DivergenceCount++;
                LastDivergence = d;
                Diverged?.Invoke(d);
            }
        }
    }
}
