using System;
using Fulcrum.Collision;

namespace Fulcrum.Components
{
    /// <summary>The one place where the components and the bridge read a world's contact events of the last step.</summary>
    internal static class WorldEvents
    {
        public static ReadOnlySpan<ContactEvent> Of(World world) => world.ContactEvents;
    }
}
