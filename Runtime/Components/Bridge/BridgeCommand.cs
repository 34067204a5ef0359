using System;
using System.Numerics;

namespace Fulcrum.Components
{
    internal enum BridgeCommandKind : byte
    {
        Create,
        Destroy,
        SetMode,
        AddForce,
        AddForceAtPosition,
        AddTorque,
        SetLinearVelocity,
        SetAngularVelocity,
        Teleport,
        SetHaptics,
    }

    /// <summary>A change requested by the game, applied by whoever steps the world, between steps.</summary>
    internal struct BridgeCommand
    {
        public BridgeCommandKind Kind;
        public int Slot;
        public int Generation;
        public IPhysicsEntity? Entity;
        public BodyDef Body;
        public int ShapeStart;
        public int ShapeCount;
        public DriveMode Mode;
        public Vector3 Vector;
        public Vector3 Point;
        public Quaternion Rotation;
        public ForceMode ForceMode;
        public bool Flag;
    }

    /// <summary>An append-only list of commands with the shapes they carry; cleared after it is applied.</summary>
    internal sealed class BridgeCommandQueue
    {
        public BridgeCommand[] Items = new BridgeCommand[32];
        public int Count;
        public ShapeDef[] Shapes = new ShapeDef[32];
        public int ShapeCount;

        public void Add(in BridgeCommand c)
        {
            if (Count == Items.Length) Array.Resize(ref Items, Items.Length * 2);
            Items[Count++] = c;
        }

        public int AddShapes(ReadOnlySpan<ShapeDef> shapes)
        {
            int start = ShapeCount;
            while (ShapeCount + shapes.Length > Shapes.Length) Array.Resize(ref Shapes, Shapes.Length * 2);
            shapes.CopyTo(new Span<ShapeDef>(Shapes, ShapeCount, shapes.Length));
            ShapeCount += shapes.Length;
            return start;
        }

        public void Clear()
        {
            // Drop references (entities, hull data) so that they can be collected.
            Array.Clear(Items, 0, Count);
            Array.Clear(Shapes, 0, ShapeCount);
            Count = 0;
            ShapeCount = 0;
        }
    }
}
