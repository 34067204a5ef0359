using System;
using Fulcrum.Collision;

namespace Fulcrum.Components
{
    /// <summary>The one place where the components and the bridge read a world's contact events of the last step.</summary>
    internal static class WorldEvents
    {
        // The narrow phase that fills the world's event buffer is not in Fulcrum.Core yet;
        // until it is, only events injected by tests are dispatched.
        public static ReadOnlySpan<ContactEvent> Of(World world) => ReadOnlySpan<ContactEvent>.Empty;
    }
}
