using System;

namespace Fulcrum
{
    /// <summary>
    /// Thrown when a handle names an object that was removed from the world (or never
    /// belonged to it). The world is left unchanged.
    /// </summary>
    public sealed class StaleHandleException : InvalidOperationException
    {
        /// <summary>Creates the exception with a message naming the handle.</summary>
        public StaleHandleException(string message) : base(message) { }
    }
}
