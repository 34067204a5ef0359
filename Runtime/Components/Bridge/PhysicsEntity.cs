using System;
using System.Numerics;

namespace Fulcrum.Components
{
    /// <summary>
    /// An <see cref="IPhysicsEntity"/> made of two delegates, for engines whose objects
    /// cannot implement the interface: <c>PhysicsEntity.From(() =&gt; (obj.Pos, obj.Rot), (p, q) =&gt; { obj.Pos = p; obj.Rot = q; })</c>.
    /// </summary>
    public sealed class PhysicsEntity : IPhysicsEntity
    {
        /// <summary>Reads a pose.</summary>
        public delegate void PoseReader(out Vector3 position, out Quaternion rotation);

        readonly PoseReader _read;
        readonly Action<Vector3, Quaternion> _write;

        PhysicsEntity(PoseReader read, Action<Vector3, Quaternion> write)
        {
            _read = read;
            _write = write;
        }

        /// <summary>Wraps a reader and a writer; the name is used in errors.</summary>
        public static PhysicsEntity From(PoseReader read, Action<Vector3, Quaternion> write, string name = "entity")
        {
            if (read == null) throw new ArgumentNullException(nameof(read), $"PhysicsEntity '{name}': read cannot be null.");
            if (write == null) throw new ArgumentNullException(nameof(write), $"PhysicsEntity '{name}': write cannot be null.");
            return new PhysicsEntity(read, write) { Name = name };
        }

        /// <summary>The name given to <see cref="From"/>.</summary>
        public string Name { get; private set; } = "entity";

        /// <inheritdoc/>
        public void GetPose(out Vector3 position, out Quaternion rotation) => _read(out position, out rotation);

        /// <inheritdoc/>
        public void SetPose(Vector3 position, Quaternion rotation) => _write(position, rotation);

        /// <inheritdoc/>
        public override string ToString() => $"PhysicsEntity '{Name}'";
    }
}
