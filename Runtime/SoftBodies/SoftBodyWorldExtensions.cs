using System;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The entry points to soft bodies. They live in this assembly so that a world that never
    /// creates one never loads it: the first <see cref="CreateSoftBody"/> installs a
    /// <see cref="SoftBodySystem"/> as the world's <see cref="World.SoftBodyStage"/>.
    /// </summary>
    public static class SoftBodyWorldExtensions
    {
        /// <summary>
        /// Creates a soft body. Every field of <paramref name="def"/> is checked before anything
        /// changes; a bad one throws an <see cref="ArgumentException"/> naming it (or the
        /// offending mesh element), a stale pin body a <see cref="StaleHandleException"/>.
        /// </summary>
        public static SoftBodyHandle CreateSoftBody(this World world, in SoftBodyDef def)
        {
            if (world == null) throw new ArgumentNullException(nameof(world));
            if (world.IsStepping) throw new InvalidOperationException("The world cannot be changed during Step (from a callback); defer the change until Step returns.");
            def.Validate();
            if (def.Pins != null)
                for (int i = 0; i < def.Pins.Length; i++)
                    if (!def.Pins[i].Body.IsNone && !world.IsValid(def.Pins[i].Body))
                        throw new StaleHandleException($"softBody.Pins[{i}].Body {def.Pins[i].Body} does not name a live body.");
            SoftBodySystem? system = SoftBodySystem.Of(world);
            if (system == null)
            {
                if (world.SoftBodyStage != null)
                    throw new InvalidOperationException("The world already has a soft-body stage of another kind.");
                system = new SoftBodySystem(world);
                SoftBodyHandle handle = system.Add(def);
                world.SoftBodyStage = system;
                return handle;
            }
            return system.Add(def);
        }

        /// <summary>Removes a soft body; its handle goes stale (removing it again throws <see cref="StaleHandleException"/>).</summary>
        public static void DestroySoftBody(this World world, SoftBodyHandle handle)
        {
            if (world.IsStepping) throw new InvalidOperationException("The world cannot be changed during Step (from a callback); defer the change until Step returns.");
            System(world, handle).Remove(handle);
        }

        /// <summary>The soft body a handle names; throws <see cref="StaleHandleException"/> if it is stale.</summary>
        public static SoftBody GetSoftBody(this World world, SoftBodyHandle handle) => System(world, handle).Get(handle);

        /// <summary>True when the handle names a live soft body of this world.</summary>
        public static bool IsValid(this World world, SoftBodyHandle handle) =>
            SoftBodySystem.Of(world) is SoftBodySystem s && s.IsLive(handle);

        /// <summary>Live soft bodies in the world (0 without the stage).</summary>
        public static int SoftBodyCount(this World world) => SoftBodySystem.Of(world)?.Count ?? 0;

        static SoftBodySystem System(World world, SoftBodyHandle handle)
        {
            SoftBodySystem? system = SoftBodySystem.Of(world);
            if (system == null)
                throw new StaleHandleException(handle.IsNone ? "The soft body handle is None." : $"{handle} does not name a live soft body: this world has none.");
            return system;
        }
    }
}
