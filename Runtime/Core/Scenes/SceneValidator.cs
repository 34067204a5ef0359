using System;
using System.Collections.Generic;
using System.Globalization;
using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// Checks a <see cref="SceneDocument"/> against the rules of the scene format: value ranges,
    /// the format tag, which shapes a body type may carry, mass versus density, and that every
    /// material, body and joint name referred to exists and every name is unique (generated
    /// names included). Each error names the JSON path of the offending value, computed from
    /// the document's structure, so documents built in code are checked the same way.
    /// </summary>
    public static class SceneValidator
    {
        /// <summary>The most bodies a scene may expand to (a typo in a count should not exhaust memory).</summary>
        public const long MaxBodies = 1_000_000;

        /// <summary>The most cells a soft mesh grid may have along one axis (the soft-body meshers' limit).</summary>
        public const int MaxGridCells = 1024;

        /// <summary>Every problem found, in document order; empty when the document is valid.</summary>
        public static IReadOnlyList<SceneError> Validate(SceneDocument doc)
        {
            var v = new SceneChecker();
            v.Document(doc);
            return v.Errors;
        }

        /// <summary>Throws a <see cref="SceneException"/> listing every problem, if there is any.</summary>
        public static void ThrowIfInvalid(SceneDocument doc)
        {
            IReadOnlyList<SceneError> errors = Validate(doc);
            if (errors.Count > 0) throw new SceneException(errors);
        }
    }
}
