using System.Numerics;

namespace Fulcrum.Components
{
    /// <summary>
    /// An object of a custom engine that a <see cref="PhysicsBridge"/> keeps in step with a
    /// body. The bridge calls these on the game thread only: <see cref="GetPose"/> in
    /// <see cref="PhysicsBridge.Register(IPhysicsEntity, in BodyDef, in ShapeDef, DriveMode)"/>
    /// and, for game-driven entities, in <see cref="PhysicsBridge.SyncFromGame"/>;
    /// <see cref="SetPose"/> in <see cref="PhysicsBridge.SyncToGame"/> for physics-driven ones.
    /// </summary>
    public interface IPhysicsEntity
    {
        /// <summary>Reads the entity's world position (metres) and rotation.</summary>
        void GetPose(out Vector3 position, out Quaternion rotation);

        /// <summary>Writes the entity's world position (metres) and rotation.</summary>
        void SetPose(Vector3 position, Quaternion rotation);
    }
}
