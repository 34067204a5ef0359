#if PEER_JITTER
using System.Numerics;
using Jitter2.Collision.Shapes;
using Jitter2.Dynamics;
using Jitter2.LinearMath;
using JitterWorld = Jitter2.World;

namespace Fulcrum.Benchmarks.Peers
{
    /// <summary>
    /// Jitter2 (built by the user and referenced with -p:JitterDir=...): SubstepCount = substeps,
    /// SolverIterations = (iterations, relax passes), damping and deactivation off, single-threaded Step.
    /// </summary>
    public sealed class JitterPeer : IPeerEngine
    {
        JitterWorld? _world;
        RigidBody[] _bodies = System.Array.Empty<RigidBody>();

        public string Name => "Jitter2";

        public int Threads => 1;

        public string Version => PeerRoster.VersionOf(typeof(JitterWorld));

        public void Build(PeerScene scene, PeerSettings settings)
        {
            var world = new JitterWorld
            {
                SubstepCount = settings.Substeps,
                SolverIterations = (settings.Iterations, settings.RelaxIterations),
                AllowDeactivation = false,
                Gravity = new JVector(0, settings.GravityY, 0),
            };

            Vector3 g = 2 * scene.Ground.HalfExtents;
            RigidBody ground = world.CreateRigidBody();
            ground.AddShape(new BoxShape(g.X, g.Y, g.Z));
            ground.Position = ToJitter(scene.Ground.Center);
            ground.Friction = settings.Friction;
            ground.MotionType = MotionType.Static;

            _bodies = new RigidBody[scene.Boxes.Count];
            for (int i = 0; i < _bodies.Length; i++)
            {
                PeerBox box = scene.Boxes[i];
                Vector3 size = 2 * box.HalfExtents;
                RigidBody body = world.CreateRigidBody();
                body.AddShape(new BoxShape(size.X, size.Y, size.Z));
                body.Position = ToJitter(box.Center);
                body.Orientation = new JQuaternion(box.Rotation.X, box.Rotation.Y, box.Rotation.Z, box.Rotation.W);
                body.SetMassInertia(settings.BoxMass);
                body.Friction = settings.Friction;
                body.Damping = (0, 0);
                _bodies[i] = body;
            }
            _world = world;
        }

        static JVector ToJitter(Vector3 v) => new JVector(v.X, v.Y, v.Z);

        public void Step(float dt) => _world!.Step(dt, multiThread: false);

        public void ReadPose(int box, out Vector3 position, out Quaternion rotation)
        {
            RigidBody body = _bodies[box];
            JVector p = body.Position;
            JQuaternion q = body.Orientation;
            position = new Vector3(p.X, p.Y, p.Z);
            rotation = new Quaternion(q.X, q.Y, q.Z, q.W);
        }

        public void Dispose()
        {
            _world?.Dispose();
            _world = null;
        }
    }
}
#endif
