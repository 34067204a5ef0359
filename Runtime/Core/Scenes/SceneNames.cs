using System;
using System.Collections.Generic;
using System.Text;

namespace Fulcrum.Scenes
{
    /// <summary>The JSON spellings of the scene format's enumerations, both ways.</summary>
    public static class SceneNames
    {
        // Each enumeration's values with their spellings, in scene-format order. Of and TryParse
        // look both ways up in these tables, and the reader lists their spellings when it meets
        // an unknown one; a value missing from a table (a cast out of range) is written as the
        // table's last entry.

        /// <summary>Body types.</summary>
        internal static readonly (BodyType Value, string Name)[] BodyTypes =
            { (BodyType.Static, "static"), (BodyType.Kinematic, "kinematic"), (BodyType.Dynamic, "dynamic") };

        /// <summary>Solver types.</summary>
        internal static readonly (SolverType Value, string Name)[] SolverTypes = { (SolverType.Pgs, "pgs"), (SolverType.Tgs, "tgs") };

        /// <summary>Shape types.</summary>
        internal static readonly (SceneShapeType Value, string Name)[] ShapeTypes =
        {
            (SceneShapeType.Sphere, "sphere"), (SceneShapeType.Box, "box"), (SceneShapeType.Capsule, "capsule"),
            (SceneShapeType.Convex, "convex"), (SceneShapeType.Plane, "plane"), (SceneShapeType.Mesh, "mesh"),
            (SceneShapeType.Compound, "compound"),
        };

        /// <summary>Joint types.</summary>
        internal static readonly (JointKind Value, string Name)[] JointKinds =
        {
            (JointKind.Ball, "ball"), (JointKind.Hinge, "hinge"), (JointKind.Distance, "distance"),
            (JointKind.Fixed, "fixed"), (JointKind.Prismatic, "prismatic"), (JointKind.ConeTwist, "coneTwist"),
        };

        /// <summary>Generator types.</summary>
        internal static readonly (SceneGeneratorType Value, string Name)[] GeneratorTypes =
        {
            (SceneGeneratorType.Tower, "tower"), (SceneGeneratorType.Pyramid, "pyramid"), (SceneGeneratorType.Wall, "wall"),
            (SceneGeneratorType.Pile, "pile"), (SceneGeneratorType.Chain, "chain"), (SceneGeneratorType.Dominoes, "dominoes"),
        };

        /// <summary>Generator axes.</summary>
        internal static readonly (SceneAxis Value, string Name)[] Axes = { (SceneAxis.X, "x"), (SceneAxis.Z, "z") };

        /// <summary>Chain anchors.</summary>
        internal static readonly (SceneChainAnchor Value, string Name)[] ChainAnchors =
            { (SceneChainAnchor.None, "none"), (SceneChainAnchor.First, "first"), (SceneChainAnchor.Both, "both") };

        /// <summary>Soft material models.</summary>
        internal static readonly (SceneSoftModel Value, string Name)[] SoftModels =
            { (SceneSoftModel.StableNeoHookean, "stable-neo-hookean"), (SceneSoftModel.NeoHookean, "neo-hookean") };

        /// <summary>Soft mesh types (obj last: the spelling of an out-of-range value, as before).</summary>
        internal static readonly (SceneSoftMeshType Value, string Name)[] SoftMeshTypes =
        {
            (SceneSoftMeshType.Box, "box"), (SceneSoftMeshType.Sphere, "sphere"), (SceneSoftMeshType.Capsule, "capsule"),
            (SceneSoftMeshType.Beam, "beam"), (SceneSoftMeshType.Cloth, "cloth"), (SceneSoftMeshType.TetGen, "tetgen"),
            (SceneSoftMeshType.Surface, "surface"), (SceneSoftMeshType.Obj, "obj"),
        };

        /// <summary>The shapes a pile generator may be made of.</summary>
        internal static readonly (SceneShapeType Value, string Name)[] PileShapes =
            { (SceneShapeType.Box, "box"), (SceneShapeType.Sphere, "sphere"), (SceneShapeType.Capsule, "capsule") };

        /// <summary>The six single axes of <see cref="AxisLocks"/> in scene order, with their scene names.</summary>
        internal static readonly (AxisLocks Axis, string Name)[] LockAxes =
        {
            (AxisLocks.LinearX, "linearX"), (AxisLocks.LinearY, "linearY"), (AxisLocks.LinearZ, "linearZ"),
            (AxisLocks.AngularX, "angularX"), (AxisLocks.AngularY, "angularY"), (AxisLocks.AngularZ, "angularZ"),
        };

        /// <summary>"static", "kinematic" or "dynamic".</summary>
        public static string Of(BodyType t) => NameOf(BodyTypes, t);

        /// <summary>"pgs" or "tgs".</summary>
        public static string Of(SolverType t) => NameOf(SolverTypes, t);

        /// <summary>"sphere", "box", "capsule", "convex", "plane", "mesh" or "compound".</summary>
        public static string Of(SceneShapeType t) => NameOf(ShapeTypes, t);

        /// <summary>"ball", "hinge", "distance", "fixed", "prismatic" or "coneTwist".</summary>
        public static string Of(JointKind t) => NameOf(JointKinds, t);

        /// <summary>"tower", "pyramid", "wall", "pile", "chain" or "dominoes".</summary>
        public static string Of(SceneGeneratorType t) => NameOf(GeneratorTypes, t);

        /// <summary>"x" or "z".</summary>
        public static string Of(SceneAxis a) => NameOf(Axes, a);

        /// <summary>"none", "first" or "both".</summary>
        public static string Of(SceneChainAnchor a) => NameOf(ChainAnchors, a);

        /// <summary>"stable-neo-hookean" or "neo-hookean".</summary>
        public static string Of(SceneSoftModel m) => NameOf(SoftModels, m);

        /// <summary>"box", "sphere", "capsule", "beam", "cloth", "tetgen", "obj" or "surface".</summary>
        public static string Of(SceneSoftMeshType t) => NameOf(SoftMeshTypes, t);

        /// <summary>Parses one <c>lockAxes</c> name (<c>"linearX"</c> .. <c>"angularZ"</c>); false for an unknown spelling.</summary>
        public static bool TryParse(string s, out AxisLocks axis) => ValueOf(LockAxes, s, AxisLocks.None, out axis);

        /// <summary>Parses a body type; false for an unknown spelling.</summary>
        public static bool TryParse(string s, out BodyType t) => ValueOf(BodyTypes, s, BodyType.Dynamic, out t);

        /// <summary>Parses a solver type; false for an unknown spelling.</summary>
        public static bool TryParse(string s, out SolverType t) => ValueOf(SolverTypes, s, SolverType.Tgs, out t);

        /// <summary>Parses a shape type; false for an unknown spelling.</summary>
        public static bool TryParse(string s, out SceneShapeType t) => ValueOf(ShapeTypes, s, SceneShapeType.Sphere, out t);

        /// <summary>Parses a joint type; false for an unknown spelling.</summary>
        public static bool TryParse(string s, out JointKind t) => ValueOf(JointKinds, s, JointKind.Ball, out t);

        /// <summary>Parses a generator type; false for an unknown spelling.</summary>
        public static bool TryParse(string s, out SceneGeneratorType t) => ValueOf(GeneratorTypes, s, SceneGeneratorType.Tower, out t);

        /// <summary>Parses an axis; false for an unknown spelling.</summary>
        public static bool TryParse(string s, out SceneAxis a) => ValueOf(Axes, s, SceneAxis.X, out a);

        /// <summary>Parses a chain anchor; false for an unknown spelling.</summary>
        public static bool TryParse(string s, out SceneChainAnchor a) => ValueOf(ChainAnchors, s, SceneChainAnchor.First, out a);

        /// <summary>Parses a soft material model; false for an unknown spelling.</summary>
        public static bool TryParse(string s, out SceneSoftModel m) => ValueOf(SoftModels, s, SceneSoftModel.StableNeoHookean, out m);

        /// <summary>Parses a soft mesh type; false for an unknown spelling.</summary>
        public static bool TryParse(string s, out SceneSoftMeshType t) => ValueOf(SoftMeshTypes, s, SceneSoftMeshType.Box, out t);

        static string NameOf<T>((T Value, string Name)[] table, T value) where T : struct, Enum
        {
            foreach ((T v, string name) in table)
                if (EqualityComparer<T>.Default.Equals(v, value)) return name;
            return table[table.Length - 1].Name;
        }

        /// <summary>The value <paramref name="s"/> spells in <paramref name="table"/>; false (and <paramref name="unknown"/>) for a spelling not in it.</summary>
        internal static bool ValueOf<T>((T Value, string Name)[] table, string s, T unknown, out T value) where T : struct, Enum
        {
            foreach ((T v, string name) in table)
                if (s == name)
                {
                    value = v;
                    return true;
                }
            value = unknown;
            return false;
        }

        /// <summary>The spellings in <paramref name="table"/>, for messages: "x, y or z".</summary>
        internal static string Spellings<T>((T Value, string Name)[] table) where T : struct, Enum
        {
            var names = new string[table.Length];
            for (int i = 0; i < table.Length; i++) names[i] = table[i].Name;
            return Spellings(names);
        }

        /// <summary><paramref name="names"/>, for messages: "x, y or z".</summary>
        internal static string Spellings(string[] names)
        {
            var sb = new StringBuilder();
            for (int i = 0; i < names.Length; i++)
                sb.Append(i == 0 ? "" : i == names.Length - 1 ? " or " : ", ").Append(names[i]);
            return sb.ToString();
        }
    }
}
