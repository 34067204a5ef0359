using System.Collections.Generic;
using System.Globalization;
using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// The checks behind <see cref="SceneValidator"/>: one walk over a document that collects
    /// every problem with the JSON path of the offending value, split by what it checks (this
    /// file: the document and the solver settings; Bodies, Names, Joints, SoftBodies, and the
    /// Values every field uses).
    /// </summary>
    internal sealed partial class SceneChecker
    {
        public readonly List<SceneError> Errors = new List<SceneError>();
        SceneDocument _doc = null!;
        bool _generatorsExpanded;

        void Error(string path, string message) => Errors.Add(new SceneError(path, message));

        static string F(float f) => f.ToString("R", CultureInfo.InvariantCulture);

        static string V(Vector3 v) => $"[{F(v.X)}, {F(v.Y)}, {F(v.Z)}]";

        static string P(string parent, string key) => JsonPath.Member(parent, key);

        public void Document(SceneDocument doc)
        {
            _doc = doc;
            const string root = JsonPath.Root;
            if (doc.Format != SceneDocument.CurrentFormat)
                Error(P(root, "format"), $"must be \"{SceneDocument.CurrentFormat}\", got {JsonPath.Quote(doc.Format ?? "")}");
            if (Finite(doc.Gravity, P(root, "gravity")) && Limits.Length(doc.Gravity) > Limits.MaxGravity)
                Error(P(root, "gravity"), $"must have magnitude at most {F(Limits.MaxGravity)} m/s^2 (Limits.MaxGravity), got {V(doc.Gravity)}");
            if (Positive(doc.Timestep, P(root, "timestep"))) Upto(doc.Timestep, Limits.MinTimeStep, Limits.MaxTimeStep, P(root, "timestep"), "Limits.MinTimeStep/MaxTimeStep");
            string solver = P(root, "solver");
            if (doc.Solver == null) Error(solver, "must not be null");
            else
            {
                if (doc.Solver.Type != SolverType.Pgs && doc.Solver.Type != SolverType.Tgs) Error(P(solver, "type"), "must be pgs or tgs");
                if (AtLeast(doc.Solver.Iterations, 1, P(solver, "iterations"))) IntInRange(doc.Solver.Iterations, 1, Limits.MaxIterations, P(solver, "iterations"));
                if (AtLeast(doc.Solver.Substeps, 1, P(solver, "substeps"))) IntInRange(doc.Solver.Substeps, 1, Limits.MaxSubsteps, P(solver, "substeps"));
                if (doc.Solver.ContactHertz is float contactHertz) Positive(contactHertz, P(solver, "contactHertz"));
                if (doc.Solver.JointHertz is float jointHertz) Positive(jointHertz, P(solver, "jointHertz"));
                if (doc.Solver.ManifoldReuse is float reuse) NonNegative(reuse, P(solver, "manifoldReuse"));
                if (doc.Solver.ShockDepth is float shockDepth) NonNegative(shockDepth, P(solver, "shockDepth"));
                if (doc.Solver.MaxJointCorrectionSpeed is float jointSpeed) Positive(jointSpeed, P(solver, "maxJointCorrectionSpeed"));
            }
            Materials();
            for (int i = 0; i < doc.Bodies.Count; i++) Body(doc.Bodies[i], JsonPath.Index("$.bodies", i));
            bool generatorsOk = Generators();
            HashSet<string> bodies = BodyNames(generatorsOk);
            _generatorsExpanded = generatorsOk;
            for (int i = 0; i < doc.Joints.Count; i++) Joint(doc.Joints[i], JsonPath.Index("$.joints", i), bodies);
            if (generatorsOk) JointNames();
            var softNames = new Dictionary<string, string>();
            for (int i = 0; i < doc.SoftBodies.Count; i++) SoftBody(doc.SoftBodies[i], JsonPath.Index("$.softBodies", i), bodies, softNames);
        }
    }
}
