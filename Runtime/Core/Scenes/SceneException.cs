using System;
using System.Collections.Generic;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// Thrown when a scene cannot be read, validated or built. <see cref="Errors"/> holds every
    /// problem found (each with its JSON path); the message is the first one, plus a count.
    /// </summary>
    public sealed class SceneException : Exception
    {
        /// <summary>Creates the exception from one or more errors.</summary>
        public SceneException(IReadOnlyList<SceneError> errors)
            : base(Describe(errors))
        {
            Errors = errors;
        }

        /// <summary>Creates the exception from one error.</summary>
        public SceneException(SceneError error) : this(new[] { error }) { }

        /// <summary>Every problem found, in document order.</summary>
        public IReadOnlyList<SceneError> Errors { get; }

        static string Describe(IReadOnlyList<SceneError> errors)
        {
            if (errors.Count == 0) return "invalid scene";
            string first = errors[0].ToString();
            return errors.Count == 1 ? first : $"{first} (and {errors.Count - 1} more)";
        }
    }
}
