using System;
using System.Numerics;
using Fulcrum.Mathematics;
using Fulcrum.SoftBodies;

namespace Fulcrum.Runner
{
    /// <summary>
    /// A seeded generator of hostile soft-body worlds (issues 11 and 12): one or two soft bodies
    /// of every mesh kind (box with each tet split, beam, sphere, capsule, cloth), both material
    /// models, Young's modulus 1e3 to 1e10 Pa, Poisson's ratio 0 to 0.4999, densities 10 to 5000
    /// kg/m³, both soft solvers, automatic or set substeps and iterations, pins to the world or
    /// to a rigid body, launches up to 20 m/s; and up to four rigid bodies of 0.01 kg to 10 t
    /// (every shape kind, <see cref="WorldFuzz"/>'s) dropped or thrown onto them; PGS or TGS,
    /// 1 or 2 threads, a level or tilted ground. The same seed always builds the same world.
    /// Used by the CI fuzz tests and by <c>fulcrum fuzz --soft</c>.
    /// </summary>
    public static class SoftFuzz
    {
        /// <summary>What a fuzzed soft world did.</summary>
        public struct Outcome
        {
            /// <summary>A one-line reason when a rigid or soft body diverged (reported by the world or the soft-body system), else null.</summary>
            public string? Failure;
            /// <summary>A one-line reason when a body got farther than its speeds allow, else null.</summary>
            public string? Escape;
            /// <summary>A one-line reason when an element ended the run inverted (J &lt;= 0), else null.</summary>
            public string? Inverted;
            /// <summary>A one-line reason when the mechanical energy rose above <see cref="EnergyAllowance"/>, else null.</summary>
            public string? EnergyGain;
            /// <summary>True when the API refused the generated input (a clear exception is a pass).</summary>
            public bool Refused;
            /// <summary>The API's message when it refused the input, else null.</summary>
            public string? Refusal;
            /// <summary>The largest rise of the mechanical energy (kinetic and potential, <see cref="Energy"/>) above its start, J.</summary>
            public double MaxEnergyRise;
            /// <summary>
            /// What the world may legitimately gain, J: every rigid body and every soft vertex
            /// moving at the contact push and joint correction speeds together.
            /// </summary>
            public double EnergyAllowance;
            /// <summary>Steps the soft-body system took again with finer substeps (<see cref="SoftBodySystem.RetriedSteps"/>).</summary>
            public int Retried;
            /// <summary>The smallest element J at the end of the run (1 for shells).</summary>
            public float EndMinJ;
        }

        /// <summary>Builds soft world <paramref name="seed"/>, runs it <paramref name="steps"/> steps and checks it.</summary>
        public static Outcome Run(int seed, int steps)
        {
            var outcome = new Outcome { EndMinJ = 1 };
            World? w = Build(seed, out BodyHandle[] rigid, out SoftBodyHandle[] soft, out float launch, out string what);
            if (w == null)
            {
                outcome.Refused = true;
                outcome.Refusal = $"seed {seed}: {what}";
                return outcome;
            }
            SoftBodySystem system = SoftBodySystem.Of(w)!;
            WorldSettings s = w.Settings;
            float time = steps / 60f;
            double mass = 0;
            foreach (BodyHandle h in rigid) mass += w.GetBody(h).Mass;
            foreach (SoftBodyHandle h in soft) mass += w.GetSoftBody(h).TotalMass;
            float correction = s.MaxJointCorrectionSpeed + s.MaxContactPushSpeed;
            outcome.EnergyAllowance = 0.5 * mass * correction * correction;
            double start = Energy(w, rigid, soft);
            float baseReach = 5 + (launch + 9.81f * time) * time;
            double maxKinetic = 0;
            var carried = new float[rigid.Length + soft.Length];
            for (int n = 0; n < steps; n++)
            {
                w.Step(1f / 60f);
                outcome.Retried = system.RetriedSteps;
                if (w.DivergenceCount > 0)
                {
                    outcome.Failure = $"seed {seed}: {w.LastDivergence} ({what})";
                    return outcome;
                }
                if (system.DivergenceCount > 0)
                {
                    outcome.Failure = $"seed {seed}: soft body {system.LastDiverged} diverged at step {system.LastDivergedStep} ({what})";
                    return outcome;
                }
                double kinetic = WorldFuzz.KineticEnergy(w, rigid);
                foreach (SoftBodyHandle h in soft) kinetic += SoftKinetic(w.GetSoftBody(h));
                maxKinetic = Math.Max(maxKinetic, kinetic);
                for (int i = 0; i < carried.Length; i++)
                {
                    float bodyMass = i < rigid.Length ? w.GetBody(rigid[i]).Mass : w.GetSoftBody(soft[i - rigid.Length]).TotalMass;
                    Vector3 at = i < rigid.Length ? w.GetBody(rigid[i]).Position : Centroid(w.GetSoftBody(soft[i - rigid.Length]));
                    float speed = (float)Math.Min(s.MaxLinearSpeed, Math.Sqrt(2 * maxKinetic / bodyMass));
                    carried[i] += speed / 60f;
                    float reach = baseReach + carried[i];
                    if (outcome.Escape == null && at.Length() > reach)
                        outcome.Escape = $"seed {seed}: body {i} at {at.Length():F0} m, beyond the {reach:F0} m its speeds allow (step {n}; {what})";
                }
                double rise = Energy(w, rigid, soft) - start;
                if (rise > outcome.MaxEnergyRise) outcome.MaxEnergyRise = rise;
                if (outcome.EnergyGain == null && rise > outcome.EnergyAllowance)
                    outcome.EnergyGain = $"seed {seed}: energy rose {rise:G3} J above its start, beyond the {outcome.EnergyAllowance:G3} J the pushes may add (step {n}; {what})";
            }
            foreach (SoftBodyHandle h in soft)
            {
                SoftBody b = w.GetSoftBody(h);
                if (b.IsShell) continue;
                var j = new float[b.ElementCount];
                b.ComputeElementJ(j);
                foreach (float x in j) outcome.EndMinJ = MathF.Min(outcome.EndMinJ, x);
            }
            if (!(outcome.EndMinJ > 0))
                outcome.Inverted = $"seed {seed}: an element ends inverted, J = {outcome.EndMinJ:G3} ({what})";
            return outcome;
        }

        /// <summary>
        /// Kinetic and gravitational energy of the rigid and soft bodies, J. Elastic energy is
        /// left out: it starts at zero (every body starts at rest shape) and is never negative,
        /// so this can only rise above its start when the motion gains energy; and in a stiff
        /// body the solver has not converged on (E 2e7 Pa cloth whipped at 80 m/s) it measures
        /// the residual strain times a stiffness of 1e7, not energy the motion holds.
        /// </summary>
        public static double Energy(World w, BodyHandle[] rigid, SoftBodyHandle[] soft)
        {
            double e = WorldFuzz.MechanicalEnergy(w, rigid);
            Vector3 g = w.Settings.Gravity;
            foreach (SoftBodyHandle h in soft)
            {
                SoftBody b = w.GetSoftBody(h);
                e += SoftKinetic(b);
                ReadOnlySpan<Vector3> x = b.Positions;
                ReadOnlySpan<float> m = b.Masses;
                for (int i = 0; i < x.Length; i++)
                    if (b.InverseMasses[i] > 0) e -= b.GravityScale * m[i] * Vector3.Dot(g, x[i]);
            }
            return e;
        }

        static double SoftKinetic(SoftBody b)
        {
            double e = 0;
            ReadOnlySpan<Vector3> v = b.Velocities;
            ReadOnlySpan<float> m = b.Masses;
            for (int i = 0; i < v.Length; i++)
                if (b.InverseMasses[i] > 0) e += 0.5 * m[i] * v[i].LengthSquared();
            return e;
        }

        static Vector3 Centroid(SoftBody b)
        {
            Vector3 c = Vector3.Zero;
            foreach (Vector3 p in b.Positions) c += p;
            return c / b.VertexCount;
        }

        /// <summary>
        /// Builds soft world <paramref name="seed"/>, or returns null when the API refused the
        /// generated input with an <see cref="ArgumentException"/>. <paramref name="what"/>
        /// summarises the world in one line for the reports.
        /// </summary>
        public static World? Build(int seed, out BodyHandle[] rigid, out SoftBodyHandle[] soft, out float launchSpeed, out string what)
        {
            var r = new Random(seed);
            float U() => (float)(r.NextDouble() * 2 - 1);
            float Range(float lo, float hi) => lo + (hi - lo) * (float)r.NextDouble();
            float LogRange(float lo, float hi) => MathF.Exp(Range(MathF.Log(lo), MathF.Log(hi)));
            Vector3 Dir() => Vector3.Normalize(new Vector3(U(), U(), U()) + new Vector3(1e-3f));
            Quaternion Turn() => Quaternion.Normalize(new Quaternion(U(), U(), U(), U() + 0.1f));

            WorldSettings s = WorldSettings.Default;
            s.Solver = r.Next(2) == 0 ? SolverType.Pgs : SolverType.Tgs;
            s.Iterations = 1 + r.Next(8);
            s.Substeps = 1 + r.Next(4);
            s.Threads = 1 + r.Next(2);
            var w = new World(s);
            int softCount = 1 + (r.Next(4) == 0 ? 1 : 0);
            int rigidCount = r.Next(5);
            rigid = new BodyHandle[rigidCount];
            soft = new SoftBodyHandle[softCount];
            launchSpeed = 0;
            what = $"{s.Solver} {s.Iterations}x{s.Substeps}";
            try
            {
                float tilt = r.Next(3) == 0 ? Range(5, 35) : 0;
                Quaternion groundTurn = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, tilt * MathF.PI / 180);
                BodyDef ground = BodyDef.Static(Vector3.Transform(new Vector3(0, -0.5f, 0), groundTurn));
                ground.Rotation = groundTurn;
                w.AddShape(w.CreateBody(ground), ShapeDef.Of(ShapeGeometry.Box(new Vector3(20, 0.5f, 20))));

                // The soft meshes and where they start: clear of the ground and of each other
                // (measured along the ground's normal), so nothing starts pressed.
                var meshes = new SoftMesh[softCount];
                var names = new string[softCount];
                var places = new Vector3[softCount];
                float top = 0;
                for (int i = 0; i < softCount; i++)
                {
                    switch (r.Next(6))
                    {
                        case 0:
                        case 1:
                            var split = (TetSplit)r.Next(3);
                            meshes[i] = SoftMesh.Box(new Vector3(Range(0.1f, 1f), Range(0.05f, 0.6f), Range(0.1f, 1f)), 1 + r.Next(5), 1 + r.Next(4), 1 + r.Next(5), split);
                            names[i] = $"box {split}";
                            break;
                        case 2:
                            meshes[i] = SoftMesh.Beam(Range(0.4f, 2f), Range(0.04f, 0.2f), 4 + r.Next(10));
                            names[i] = "beam";
                            break;
                        case 3:
                            meshes[i] = SoftMesh.Sphere(Range(0.08f, 0.5f), 3 + r.Next(4));
                            names[i] = "sphere";
                            break;
                        case 4:
                            meshes[i] = SoftMesh.Capsule(Range(0.05f, 0.3f), Range(0.05f, 0.4f), 3 + r.Next(3));
                            names[i] = "capsule";
                            break;
                        default:
                            meshes[i] = SoftMesh.Cloth(Range(0.3f, 2f), Range(0.3f, 2f), 3 + r.Next(14), 3 + r.Next(14));
                            names[i] = "cloth";
                            break;
                    }
                    float radius = Radius(meshes[i]);
                    float height = top + radius + 0.02f + Range(0, 1);
                    places[i] = new Vector3(U() * 0.3f, height, U() * 0.3f);
                    top = height + radius;
                }

                // Rigid bodies above them, one over another (their shapes reach at most 1.2 m
                // from their centres), dropped or thrown.
                for (int i = 0; i < rigidCount; i++)
                {
                    float height = top + 1.2f + Range(0.02f, 1f);
                    top = height + 1.2f;
                    BodyDef d = BodyDef.Dynamic(Vector3.Transform(new Vector3(U() * 0.3f, height, U() * 0.3f), groundTurn));
                    d.Rotation = Turn();
                    d.Mass = LogRange(0.01f, 1e4f);
                    if (r.Next(4) == 0)
                    {
                        d.LinearVelocity = Dir() * Range(0, 30);
                        d.AngularVelocity = Dir() * Range(0, 20);
                    }
                    launchSpeed = MathF.Max(launchSpeed, d.LinearVelocity.Length() + 1.5f * d.AngularVelocity.Length());
                    rigid[i] = w.CreateBody(d);
                    w.AddShape(rigid[i], ShapeDef.Of(WorldFuzz.RandomShape(r)));
                }
                for (int i = 0; i < softCount; i++)
                {
                    SoftMesh mesh = meshes[i];
                    float nu = r.Next(4) switch { 0 => Range(0f, 0.3f), 1 => Range(0.3f, 0.49f), 2 => 0.49f, _ => 0.4999f };
                    var material = new NeoHookeanMaterial(r.Next(4) == 0 ? MaterialModel.NeoHookean : MaterialModel.StableNeoHookean,
                        LogRange(1e3f, 1e10f), nu, LogRange(10f, 5000f));
                    SoftBodyDef def = SoftBodyDef.Of(mesh, material, Vector3.Transform(places[i], groundTurn));
                    def.Rotation = Turn();
                    if (!mesh.IsShell && r.Next(3) == 0) def.Solver = SoftSolver.Newton;
                    if (r.Next(3) == 0) def.Substeps = 1 + r.Next(30);
                    if (r.Next(4) == 0) def.Iterations = 1 + r.Next(4);
                    def.DampingTime = r.Next(3) == 0 ? Range(0, 0.05f) : def.DampingTime;
                    def.Friction = Range(0, 1);
                    if (r.Next(5) == 0)
                    {
                        def.LinearVelocity = Dir() * Range(0, 20);
                        launchSpeed = MathF.Max(launchSpeed, def.LinearVelocity.Length());
                    }
                    string pin = "";
                    if (r.Next(4) == 0)
                    {
                        // The vertices at one end of the rest mesh, to the world or to a rigid body.
                        Aabb bounds = mesh.Bounds;
                        Vector3 max = bounds.Max;
                        max.X = bounds.Min.X + 0.1f * (bounds.Max.X - bounds.Min.X);
                        bool toBody = rigidCount > 0 && r.Next(2) == 0;
                        def.Pins = new[] { toBody ? SoftPin.ToBody(bounds.Min, max, rigid[r.Next(rigidCount)]) : SoftPin.ToWorld(bounds.Min, max) };
                        pin = toBody ? ", pinned to a body" : ", pinned";
                    }
                    soft[i] = w.CreateSoftBody(def);
                    what += $"; {names[i]} {material.Model} E {material.YoungsModulus:G3} nu {nu:G4} rho {material.Density:G3} {def.Solver} {def.Substeps}x{def.Iterations}{pin}";
                }
                if (rigidCount > 0) what += $"; {rigidCount} rigid";
            }
            catch (ArgumentException e)
            {
                what = e.Message;
                return null; // refused with a clear error: a pass
            }
            return w;
        }

        // The farthest a rest vertex lies from the mesh's origin, m (the body is placed and turned about it).
        static float Radius(SoftMesh mesh)
        {
            float r = 0;
            foreach (Vector3 v in mesh.Vertices) r = MathF.Max(r, v.Length());
            return r;
        }
    }
}
