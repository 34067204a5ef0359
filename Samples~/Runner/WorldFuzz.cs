using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Runner
{
    /// <summary>
    /// A seeded generator of hostile worlds (issue 11): every shape kind (sphere, box, capsule,
    /// hull, compounds with offset rotated children, thin plates), masses 0.01 to 1e4 kg,
    /// speeds up to 100 m/s, 0-6 joints of every kind with random anchors, axes and limits
    /// (bodies overlapping or misaligned at step 1), PGS or TGS with random iterations, substeps,
    /// relax passes and 1-2 threads, gravity on or off, a ground box or none. The same seed
    /// always builds the same world. Used by the CI fuzz tests (Tests/Robustness) and by
    /// <c>fulcrum fuzz</c> for longer runs.
    /// </summary>
    public static class WorldFuzz
    {
        /// <summary>What a fuzzed world did.</summary>
        public struct Outcome
        {
            /// <summary>A one-line reason when the world diverged (NaN, or beyond the world bounds), else null.</summary>
            public string? Failure;
            /// <summary>A one-line reason when a body got farther than its speeds allow (an energy blow-up short of divergence), else null.</summary>
            public string? Escape;
            /// <summary>True when the API refused the generated input (a clear exception is a pass).</summary>
            public bool Refused;
            /// <summary>The largest kinetic energy over the run, J.</summary>
            public float MaxKinetic;
            /// <summary>
            /// A one-line reason when the world's mechanical energy rose above what gravity,
            /// the motors and the correction passes may add (<see cref="EnergyAllowance"/>), else null.
            /// </summary>
            public string? EnergyGain;
            /// <summary>The largest rise of mechanical energy (kinetic, rotational and potential) above its start, J.</summary>
            public double MaxEnergyRise;
            /// <summary>
            /// What the world may legitimately gain, J: the motors' work (maximum torque times
            /// target speed, over the run) plus the kinetic energy of every body moving at the
            /// joint correction and contact push speeds together (what the passes that pull
            /// violated joints together and push overlaps apart may impart).
            /// </summary>
            public double EnergyAllowance;
        }

        /// <summary>Builds world <paramref name="seed"/>, runs it <paramref name="steps"/> steps and checks it.</summary>
        public static Outcome Run(int seed, int steps)
        {
            var outcome = new Outcome();
            World? w = BuildWithBudget(seed, out BodyHandle[] handles, out Budget budget);
            if (w == null)
            {
                outcome.Refused = true;
                return outcome;
            }
            WorldSettings s = w.Settings;
            float time = steps / 60f;
            double mass = 0;
            foreach (BodyHandle h in handles) mass += w.GetBody(h).Mass;

            // What the world may gain: the motors' work, every body moving at the correction
            // speeds, and every body lifted by the largest joint error it was created with (the
            // passes that pull violated joints together may raise bodies that far).
            float correction = s.MaxJointCorrectionSpeed + s.MaxContactPushSpeed;
            outcome.EnergyAllowance = budget.MotorPower * time + 0.5 * mass * correction * correction
                                      + mass * s.Gravity.Length() * budget.JointError;
            double start = MechanicalEnergy(w, handles);

            // The farthest a body may get: its start, its launch speed and free fall over the
            // run, plus, step by step, the speed at which it would carry all the kinetic energy
            // the world has had so far (a light body struck or whipped by a heavy one may take
            // much of it; the energy check above bounds that energy), capped at the speed cap.
            float baseReach = 5 + (budget.LaunchSpeed + 9.81f * time) * time;
            var carried = new float[handles.Length];
            double maxKinetic = 0;
            for (int n = 0; n < steps; n++)
            {
                w.Step(1f / 60f);
                if (w.DivergenceCount > 0)
                {
                    outcome.Failure = $"seed {seed}: {w.LastDivergence} ({s.Solver}, {s.Iterations}x{s.Substeps}, relax {s.RelaxIterations})";
                    return outcome;
                }
                double kinetic = KineticEnergy(w, handles);
                maxKinetic = Math.Max(maxKinetic, kinetic);
                outcome.MaxKinetic = (float)maxKinetic;
                for (int i = 0; i < handles.Length; i++)
                {
                    BodyRef b = w.GetBody(handles[i]);
                    float speed = (float)Math.Min(s.MaxLinearSpeed, Math.Sqrt(2 * maxKinetic / b.Mass));
                    carried[i] += speed / 60f;
                    float reach = baseReach + carried[i];
                    if (outcome.Escape == null && b.Position.Length() > reach)
                        outcome.Escape = $"seed {seed}: {handles[i]} at {b.Position.Length():F0} m, beyond the {reach:F0} m its speeds allow (step {n}; {s.Solver}, {s.Iterations}x{s.Substeps})";
                }
                double rise = MechanicalEnergy(w, handles) - start;
                if (rise > outcome.MaxEnergyRise) outcome.MaxEnergyRise = rise;
                if (outcome.EnergyGain == null && rise > outcome.EnergyAllowance)
                    outcome.EnergyGain = $"seed {seed}: energy rose {rise:G3} J above its start, beyond the {outcome.EnergyAllowance:G3} J motors and corrections may add (step {n}; {s.Solver}, {s.Iterations}x{s.Substeps}, relax {s.RelaxIterations})";
            }
            return outcome;
        }

        /// <summary>
        /// Kinetic (linear and rotational) plus gravitational potential energy of the bodies, J:
        /// the quantity an energy-stable solver never raises beyond what motors and
        /// corrections add.
        /// </summary>
        public static double MechanicalEnergy(World w, BodyHandle[] handles)
        {
            Vector3 g = w.Settings.Gravity;
            double e = KineticEnergy(w, handles);
            foreach (BodyHandle h in handles)
            {
                BodyRef b = w.GetBody(h);
                if (b.Type == BodyType.Dynamic) e -= b.Mass * Vector3.Dot(g, b.CenterOfMass);
            }
            return e;
        }

        /// <summary>Kinetic energy, linear and rotational, of the bodies, J.</summary>
        public static double KineticEnergy(World w, BodyHandle[] handles)
        {
            double e = 0;
            foreach (BodyHandle h in handles)
            {
                BodyRef b = w.GetBody(h);
                if (b.Type != BodyType.Dynamic) continue;
                Vector3 local = Vector3.Transform(b.AngularVelocity, Quaternion.Conjugate(b.Rotation));
                e += 0.5 * b.Mass * b.LinearVelocity.LengthSquared()
                   + 0.5 * Vector3.Dot(local, b.InertiaLocal * local);
            }
            return e;
        }

        /// <summary>
        /// Builds world <paramref name="seed"/> (the same seed always builds the same world), or
        /// returns null when the API refused the generated input with an <see cref="ArgumentException"/>.
        /// </summary>
        public static World? Build(int seed, out BodyHandle[] handles, out float maxSpeed)
        {
            World? w = BuildWithBudget(seed, out handles, out Budget budget);
            maxSpeed = budget.LaunchSpeed;
            return w;
        }

        /// <summary>What a fuzzed world was given that may legitimately move or lift its bodies.</summary>
        public struct Budget
        {
            /// <summary>The fastest launch, m/s: |v| + |w| r over the bodies (r = 1.5 m).</summary>
            public float LaunchSpeed;
            /// <summary>The motors' power bound: the sum of maximum torque times target speed, W.</summary>
            public float MotorPower;
            /// <summary>The largest distance between a joint's two anchors at creation, m.</summary>
            public float JointError;
        }

        /// <summary>
        /// <see cref="Build(int, out BodyHandle[], out float)"/>, giving the whole <see cref="Budget"/>.
        /// </summary>
        public static World? BuildWithBudget(int seed, out BodyHandle[] handles, out Budget budget)
        {
            var r = new Random(seed);
            float U() => (float)(r.NextDouble() * 2 - 1);
            float Range(float lo, float hi) => lo + (hi - lo) * (float)r.NextDouble();
            float LogRange(float lo, float hi) => MathF.Exp(Range(MathF.Log(lo), MathF.Log(hi)));
            Vector3 Dir() => Vector3.Normalize(new Vector3(U(), U(), U()) + new Vector3(1e-3f));

            WorldSettings s = WorldSettings.Default;
            s.Solver = r.Next(2) == 0 ? SolverType.Pgs : SolverType.Tgs;
            s.Iterations = 1 + r.Next(8);
            s.Substeps = 1 + r.Next(8);
            s.RelaxIterations = r.Next(3);
            s.Threads = 1 + r.Next(2);
            s.BlockSolver = r.Next(4) != 0;
            bool gravity = r.Next(4) != 0;
            if (!gravity) s.Gravity = Vector3.Zero;
            var w = new World(s);
            int bodies = 2 + r.Next(7);
            handles = new BodyHandle[bodies];
            budget = default;
            try
            {
                if (r.Next(3) != 0)
                    w.AddShape(w.CreateBody(BodyDef.Static(new Vector3(0, -0.5f, 0))), ShapeDef.Of(ShapeGeometry.Box(new Vector3(20, 0.5f, 20))));
                for (int i = 0; i < bodies; i++)
                {
                    BodyDef d = BodyDef.Dynamic(new Vector3(U() * 1.5f, Range(0.2f, 3f), U() * 1.5f));
                    d.Rotation = Quaternion.Normalize(new Quaternion(U(), U(), U(), U() + 0.1f));
                    d.Mass = LogRange(0.01f, 1e4f);
                    if (r.Next(5) == 0)
                    {
                        d.LinearVelocity = Dir() * Range(0, 100);
                        d.AngularVelocity = Dir() * Range(0, 30);
                    }
                    // A point of a spinning body moves at up to |v| + |w| r: joint anchors lie within
                    // 0.6 sqrt 3 m of the centre and shapes within 1.5 m, so whatever is carried
                    // or whipped by this body may legitimately reach that speed.
                    budget.LaunchSpeed = MathF.Max(budget.LaunchSpeed, d.LinearVelocity.Length() + 1.5f * d.AngularVelocity.Length());
                    BodyHandle b = w.CreateBody(d);
                    int children = r.Next(4) == 0 ? 2 + r.Next(2) : 1;
                    for (int c = 0; c < children; c++)
                    {
                        ShapeDef shape = ShapeDef.Of(RandomShape(r));
                        if (children > 1) shape.LocalPose = new Pose(new Vector3(U(), U(), U()) * 0.6f, Quaternion.Normalize(new Quaternion(U(), U(), U(), U() + 0.1f)));
                        w.AddShape(b, shape);
                    }
                    handles[i] = b;
                }
                int joints = r.Next(7);
                for (int k = 0; k < joints; k++)
                {
                    BodyHandle a = handles[r.Next(bodies)];
                    BodyHandle b = r.Next(5) == 0 ? BodyHandle.None : handles[r.Next(bodies)];
                    if (a.Equals(b)) continue;
                    Vector3 anchorA = new Vector3(U(), U(), U()) * 0.6f;
                    Vector3 anchorB = b.IsNone ? new Vector3(U() * 2, Range(0.5f, 4), U() * 2) : new Vector3(U(), U(), U()) * 0.6f;
                    JointDef j;
                    switch (r.Next(6))
                    {
                        case 0: j = JointDef.Ball(a, b, anchorA, anchorB); break;
                        case 1:
                            j = JointDef.Hinge(a, b, anchorA, anchorB, Dir(), Dir());
                            if (r.Next(2) == 0) { j.LowerDeg = Range(-90, 0); j.UpperDeg = Range(0, 90); }
                            if (r.Next(3) == 0)
                            {
                                j.MotorSpeed = Range(-20, 20);
                                j.MaxMotorTorque = LogRange(1, 1e4f);
                                budget.MotorPower += j.MaxMotorTorque * MathF.Abs(j.MotorSpeed);
                            }
                            break;
                        case 2:
                            float min = Range(0, 1);
                            j = JointDef.Distance(a, b, anchorA, anchorB, min, r.Next(2) == 0 ? min : min + Range(0, 1));
                            break;
                        case 3: j = JointDef.Fixed(a, b, anchorA, anchorB); break;
                        case 4:
                            j = JointDef.Prismatic(a, b, anchorA, anchorB, Dir());
                            if (r.Next(2) == 0) { j.Lower = Range(-1, 0); j.Upper = Range(0, 1); }
                            break;
                        default: j = JointDef.ConeTwist(a, b, anchorA, anchorB, Dir(), Dir(), Range(5, 90), Range(5, 90)); break;
                    }
                    j.CollideConnected = r.Next(2) == 0;
                    w.CreateJoint(j);
                    budget.JointError = MathF.Max(budget.JointError, Vector3.Distance(Anchor(w, a, anchorA), Anchor(w, b, anchorB)));
                }
            }
            catch (ArgumentException)
            {
                return null; // refused with a clear error: a pass
            }
            return w;
        }

        // A joint anchor in world space (body-local for a body, world for BodyHandle.None).
        static Vector3 Anchor(World w, BodyHandle body, Vector3 local)
        {
            if (body.IsNone) return local;
            BodyRef b = w.GetBody(body);
            return b.Position + Vector3.Transform(local, b.Rotation);
        }

        internal static ShapeGeometry RandomShape(Random r)
        {
            float Range(float lo, float hi) => lo + (hi - lo) * (float)r.NextDouble();
            switch (r.Next(5))
            {
                case 0: return ShapeGeometry.Sphere(Range(0.05f, 0.6f));
                case 1: return ShapeGeometry.Box(new Vector3(Range(0.05f, 0.6f), Range(0.05f, 0.6f), Range(0.05f, 0.6f)));
                case 2: return ShapeGeometry.Box(new Vector3(Range(0.2f, 0.8f), Range(0.005f, 0.02f), Range(0.2f, 0.8f))); // a thin plate
                case 3: return ShapeGeometry.Capsule(Range(0.05f, 0.3f), Range(0.05f, 0.6f));
                default:
                {
                    Span<Vector3> points = stackalloc Vector3[12];
                    for (int i = 0; i < points.Length; i++)
                        points[i] = new Vector3(Range(-0.4f, 0.4f), Range(-0.4f, 0.4f), Range(-0.4f, 0.4f));
                    return ShapeGeometry.ConvexHull(points);
                }
            }
        }
    }
}
