using System.Numerics;
using Fulcrum;
using Fulcrum.Components;

namespace BridgeSample
{
    /// <summary>
    /// The sample's physics side: a floor and a paddle that the game moves, and a ball that
    /// physics moves. The console program and the Unity behaviour register their own objects
    /// (anything implementing <see cref="IPhysicsEntity"/>) through <see cref="Create"/>.
    /// </summary>
    public static class BridgeScene
    {
        /// <summary>How fast the game slides the paddle along +x, metres per second.</summary>
        public const float PaddleSpeed = 2f;

        /// <summary>Starting positions (metres): the floor's top is at y = 0.</summary>
        public static readonly Vector3 FloorStart = new Vector3(0, -0.5f, 0), PaddleStart = new Vector3(-3, 0.5f, 0), BallStart = new Vector3(0, 2, 0);

        /// <summary>
        /// A bridge stepping at <see cref="PhysicsBridgeSettings.FixedDt"/> = 1/120 s, on a
        /// 120 Hz physics thread when <paramref name="threaded"/>, with the three entities
        /// registered; the ball's haptics stream is on unless threaded.
        /// </summary>
        public static PhysicsBridge Create(IPhysicsEntity floor, IPhysicsEntity paddle, IPhysicsEntity ball, IBridgeContactListener listener, bool threaded)
        {
            PhysicsBridgeSettings settings = PhysicsBridgeSettings.Default;
            settings.FixedDt = 1f / 120f;
            if (threaded) settings.ThreadRateHz = 120;
            var bridge = new PhysicsBridge(new World(), settings) { ContactListener = listener };
            bridge.Register(floor, BodyDef.Static(default), ShapeDef.Of(ShapeGeometry.Box(new Vector3(10, 0.5f, 10))), DriveMode.Game);
            bridge.Register(paddle, BodyDef.Default, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.25f, 0.5f, 1))), DriveMode.Game);
            BodyDef ballDef = BodyDef.Default;
            ballDef.Mass = 1f;
            ProxyHandle b = bridge.Register(ball, ballDef, ShapeDef.Of(ShapeGeometry.Sphere(0.5f)));
            if (!threaded) bridge.SetHaptics(b, true);
            return bridge;
        }
    }
}
