namespace Fulcrum.Scenes
{
    /// <summary>The JSON spellings of the scene format's enumerations, both ways.</summary>
    public static class SceneNames
    {
        /// <summary>"static", "kinematic" or "dynamic".</summary>
        public static string Of(BodyType t) => t == BodyType.Static ? "static" : t == BodyType.Kinematic ? "kinematic" : "dynamic";

        /// <summary>"pgs" or "tgs".</summary>
        public static string Of(SolverType t) => t == SolverType.Pgs ? "pgs" : "tgs";

        /// <summary>"sphere", "box", "capsule", "convex", "plane", "mesh" or "compound".</summary>
        public static string Of(SceneShapeType t) => t switch
        {
            SceneShapeType.Sphere => "sphere",
            SceneShapeType.Box => "box",
            SceneShapeType.Capsule => "capsule",
            SceneShapeType.Convex => "convex",
            SceneShapeType.Plane => "plane",
            SceneShapeType.Mesh => "mesh",
            _ => "compound",
        };

        /// <summary>"ball", "hinge", "distance", "fixed", "prismatic" or "coneTwist".</summary>
        public static string Of(JointKind t) => t switch
        {
            JointKind.Ball => "ball",
            JointKind.Hinge => "hinge",
            JointKind.Distance => "distance",
            JointKind.Fixed => "fixed",
            JointKind.Prismatic => "prismatic",
            _ => "coneTwist",
        };

        /// <summary>"tower", "pyramid", "wall", "pile", "chain" or "dominoes".</summary>
        public static string Of(SceneGeneratorType t) => t switch
        {
            SceneGeneratorType.Tower => "tower",
            SceneGeneratorType.Pyramid => "pyramid",
            SceneGeneratorType.Wall => "wall",
            SceneGeneratorType.Pile => "pile",
            SceneGeneratorType.Chain => "chain",
            _ => "dominoes",
        };

        /// <summary>"x" or "z".</summary>
        public static string Of(SceneAxis a) => a == SceneAxis.X ? "x" : "z";

        /// <summary>"none", "first" or "both".</summary>
        public static string Of(SceneChainAnchor a) => a == SceneChainAnchor.None ? "none" : a == SceneChainAnchor.First ? "first" : "both";

        /// <summary>"stable-neo-hookean" or "neo-hookean".</summary>
        public static string Of(SceneSoftModel m) => m == SceneSoftModel.StableNeoHookean ? "stable-neo-hookean" : "neo-hookean";

        /// <summary>"box", "sphere", "capsule", "beam", "cloth", "tetgen", "obj" or "surface".</summary>
        public static string Of(SceneSoftMeshType t) => t switch
        {
            SceneSoftMeshType.Box => "box",
            SceneSoftMeshType.Sphere => "sphere",
            SceneSoftMeshType.Capsule => "capsule",
            SceneSoftMeshType.Beam => "beam",
            SceneSoftMeshType.Cloth => "cloth",
            SceneSoftMeshType.TetGen => "tetgen",
            SceneSoftMeshType.Surface => "surface",
            _ => "obj",
        };

        /// <summary>The six single axes of <see cref="AxisLocks"/> in scene order, with their scene names.</summary>
        internal static readonly (AxisLocks Axis, string Name)[] LockAxes =
        {
            (AxisLocks.LinearX, "linearX"), (AxisLocks.LinearY, "linearY"), (AxisLocks.LinearZ, "linearZ"),
            (AxisLocks.AngularX, "angularX"), (AxisLocks.AngularY, "angularY"), (AxisLocks.AngularZ, "angularZ"),
        };

        /// <summary>Parses one <c>lockAxes</c> name (<c>"linearX"</c> .. <c>"angularZ"</c>); false for an unknown spelling.</summary>
        public static bool TryParse(string s, out AxisLocks axis)
        {
            foreach ((AxisLocks a, string name) in LockAxes)
                if (s == name)
                {
                    axis = a;
                    return true;
                }
            axis = AxisLocks.None;
            return false;
        }

        /// <summary>Parses a body type; false for an unknown spelling.</summary>
        public static bool TryParse(string s, out BodyType t)
        {
            switch (s)
            {
                case "static": t = BodyType.Static; return true;
                case "kinematic": t = BodyType.Kinematic; return true;
                case "dynamic": t = BodyType.Dynamic; return true;
                default: t = BodyType.Dynamic; return false;
            }
        }

        /// <summary>Parses a solver type; false for an unknown spelling.</summary>
        public static bool TryParse(string s, out SolverType t)
        {
            switch (s)
            {
                case "pgs": t = SolverType.Pgs; return true;
                case "tgs": t = SolverType.Tgs; return true;
                default: t = SolverType.Tgs; return false;
            }
        }

        /// <summary>Parses a shape type; false for an unknown spelling.</summary>
        public static bool TryParse(string s, out SceneShapeType t)
        {
            for (t = SceneShapeType.Sphere; t <= SceneShapeType.Compound; t++)
                if (Of(t) == s) return true;
            t = SceneShapeType.Sphere;
            return false;
        }

        /// <summary>Parses a joint type; false for an unknown spelling.</summary>
        public static bool TryParse(string s, out JointKind t)
        {
            for (t = JointKind.Ball; t <= JointKind.ConeTwist; t++)
                if (Of(t) == s) return true;
            t = JointKind.Ball;
            return false;
        }

        /// <summary>Parses a generator type; false for an unknown spelling.</summary>
        public static bool TryParse(string s, out SceneGeneratorType t)
        {
            for (t = SceneGeneratorType.Tower; t <= SceneGeneratorType.Dominoes; t++)
                if (Of(t) == s) return true;
            t = SceneGeneratorType.Tower;
            return false;
        }

        /// <summary>Parses an axis; false for an unknown spelling.</summary>
        public static bool TryParse(string s, out SceneAxis a)
        {
            a = s == "z" ? SceneAxis.Z : SceneAxis.X;
            return s == "x" || s == "z";
        }

        /// <summary>Parses a chain anchor; false for an unknown spelling.</summary>
        public static bool TryParse(string s, out SceneChainAnchor a)
        {
            for (a = SceneChainAnchor.None; a <= SceneChainAnchor.Both; a++)
                if (Of(a) == s) return true;
            a = SceneChainAnchor.First;
            return false;
        }

        /// <summary>Parses a soft material model; false for an unknown spelling.</summary>
        public static bool TryParse(string s, out SceneSoftModel m)
        {
            m = s == "neo-hookean" ? SceneSoftModel.NeoHookean : SceneSoftModel.StableNeoHookean;
            return s == "neo-hookean" || s == "stable-neo-hookean";
        }

        /// <summary>Parses a soft mesh type; false for an unknown spelling.</summary>
        public static bool TryParse(string s, out SceneSoftMeshType t)
        {
            for (t = SceneSoftMeshType.Box; t <= SceneSoftMeshType.Surface; t++)
                if (Of(t) == s) return true;
            t = SceneSoftMeshType.Box;
            return false;
        }
    }
}
