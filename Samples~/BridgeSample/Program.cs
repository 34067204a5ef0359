using System;
using System.Numerics;
using Fulcrum.Components;

namespace BridgeSample
{
    /// <summary>
    /// A custom engine's game loop driving Fulcrum through the PhysicsBridge (the loose
    /// integration): the engine keeps its own objects; the bridge reads the game-driven ones,
    /// steps at a fixed rate, reports contacts and writes the physics-driven ones back.
    /// </summary>
    public static class Program
    {
        /// <summary>The custom engine's object: Fulcrum only sees it through IPhysicsEntity.</summary>
        sealed class GameObject : IPhysicsEntity
        {
            public readonly string Name;
            public Vector3 Position;
            public Quaternion Rotation = Quaternion.Identity;
            public GameObject(string name, Vector3 position) { Name = name; Position = position; }
            public void GetPose(out Vector3 position, out Quaternion rotation) { position = Position; rotation = Rotation; }
            public void SetPose(Vector3 position, Quaternion rotation) { Position = position; Rotation = rotation; }
            public override string ToString() => Name;
        }

        sealed class ContactPrinter : IBridgeContactListener
        {
            public int Count;
            public void OnContact(in BridgeContact c)
            {
                if (c.Kind == Fulcrum.Collision.ContactEventKind.Persist) return;
                Count++;
                Console.WriteLine($"  {c.Kind} {c.EntityA} / {c.EntityB} at t = {c.Time:F3} s, impulse {c.NormalImpulse:F2} N s");
            }
        }

        public static int Main(string[] args)
        {
            bool threaded = args.Length > 0 && args[0] == "--thread";
            var printer = new ContactPrinter();
            var floor = new GameObject("floor", BridgeScene.FloorStart);
            var paddle = new GameObject("paddle", BridgeScene.PaddleStart);
            var ball = new GameObject("ball", BridgeScene.BallStart);

            using (PhysicsBridge bridge = BridgeScene.Create(floor, paddle, ball, printer, threaded))
            {
                Console.WriteLine(threaded ? "bridge with a 120 Hz physics thread under a 60 Hz loop" : "bridge stepping at 120 Hz inside a 60 Hz loop");
                const float frame = 1f / 60f;
                for (int f = 0; f < 90; f++)
                {
                    paddle.Position.X += BridgeScene.PaddleSpeed * frame;   // game logic moves the paddle
                    bridge.SyncFromGame();
                    bridge.Step(frame);
                    bridge.SyncToGame();              // the renderer would draw here
                    if (threaded) System.Threading.Thread.Sleep(16);
                }
                Console.WriteLine($"ball at ({ball.Position.X:F2}, {ball.Position.Y:F2}, {ball.Position.Z:F2}), paddle at x = {paddle.Position.X:F2}, {printer.Count} begin/end events");
                if (bridge.Haptics != null) Console.WriteLine($"haptics samples waiting: {bridge.Haptics.Count}");
            }
            return 0;
        }
    }
}
