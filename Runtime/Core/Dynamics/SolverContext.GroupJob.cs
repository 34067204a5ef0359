using System.Numerics;

namespace Fulcrum.Dynamics
{
    internal sealed partial class SolverContext
    {
        // ---- the per-step passes over independent items, split between threads ----------
        // Preparing the wide groups, carrying their impulses at the end of a substep and of the
        // step, and writing the solver bodies back each touch one group (or one body) only, so
        // unlike the colour passes they need no colouring and run as one range each. They were
        // the serial part of a threaded solve: about a quarter of the 40-pyramid scene's solve
        // stage on one thread, mostly the wide prepare. The results do not depend on the split.

        /// <summary>What <see cref="GroupJob"/> does with its range.</summary>
        enum GroupPass : byte { LoadBodies, PrepareWide, Accumulate, StoreImpulses, StoreBodies }

        /// <summary>Items a thread takes at a time, per pass: below this the split costs more than it saves.</summary>
        const int MinGroupChunk = 16, MinBodyChunk = 256;

        void RunGroups(GroupPass pass, int count, int minChunk)
        {
            GroupJob job = _groupJob;
            job.Pass = pass;
            if (Pool != null) Pool.For(job, 0, count, minChunk);
            else job.Execute(0, count);
        }

        /// <summary>One of <see cref="GroupPass"/> over the wide groups (or solver bodies) [start, end).</summary>
        sealed class GroupJob : IParallelJob
        {
            readonly SolverContext _c;
            public GroupPass Pass;
            /// <summary>Warm-start scale of the step's contacts (<see cref="GroupPass.PrepareWide"/>).</summary>
            public float WarmContacts { get; set; }
            /// <summary>Impulse scale from substep to step (<see cref="GroupPass.StoreImpulses"/>).</summary>
            public float Scale { get; set; }
            /// <summary>Set when a prepared group has restitution (only ever set to true, so any thread may write it).</summary>
            public bool Restitution { get; set; }

            public GroupJob(SolverContext context) => _c = context;

            public void Execute(int start, int end)
            {
                SolverContext c = _c;
                switch (Pass)
                {
                    // The wide passes live with the rest of the SIMD path (SolverContext.Wide.cs).
                    case GroupPass.PrepareWide:
                        if (c.PrepareWideGroups(start, end, WarmContacts)) Restitution = true;
                        break;
                    case GroupPass.Accumulate:
                        c.AccumulateWideGroups(start, end);
                        break;
                    case GroupPass.StoreImpulses:
                        c.StoreWideGroups(start, end, Scale);
                        break;
                    case GroupPass.LoadBodies:
                        c.LoadBodies(start + 1, end + 1);
                        break;
                    case GroupPass.StoreBodies:
                        // Solver index k = start + 1 ...: index 0 is the fixed body.
                        c.StoreBodies(start + 1, end + 1);
                        break;
                }
            }
        }

        // Writes the solver bodies [start, end) back: velocities (dynamic ones, speed-capped),
        // then pose, origin and world inertia.
        void StoreBodies(int start, int end)
        {
            BodyStorage s = _storage;
            for (int k = start; k < end; k++)
            {
                ref SolverBody body = ref Bodies[k];
                int i = BodySlot[k];
                if (body.IsDynamic != 0)
                {
                    Vector3 v = body.LinearVelocity, w = body.AngularVelocity;
                    // The relax and restitution passes run after the capped position integration:
                    // cap what they leave too, so no body ends a step above the documented speeds
                    // (a 0.3 kg body between conflicting joints reported 4000 m/s).
                    Integrator.ClampSpeed(_settings.MaxLinearSpeed, s.Radius[i], ref v, ref w);
                    s.LinearVelocity[i] = v;
                    s.AngularVelocity[i] = w;
                }
                s.Center[i] = _startCenter[k] + body.DeltaPosition;
                s.Rotation[i] = Quaternion.Normalize(body.DeltaRotation * _startRotation[k]);
                s.SyncOriginFromCenter(i);
                s.UpdateWorldInertia(i);
            }
        }

        /// <summary>
        /// <see cref="StoreVelocities"/> then <see cref="StorePositions"/> in one pass over the
        /// bodies, split between threads (TGS's end of step).
        /// </summary>
        public void StoreBodies() => RunGroups(GroupPass.StoreBodies, BodyCount - 1, MinBodyChunk);
    }
}
