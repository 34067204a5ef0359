#if PEER_BEPU
using System.Numerics;
using BepuPhysics;
using BepuPhysics.Collidables;
using BepuPhysics.Constraints;
using BepuUtilities;
using BepuUtilities.Memory;
using BepuBodyHandle = BepuPhysics.BodyHandle;

namespace Fulcrum.Benchmarks.Peers
{
    /// <summary>
    /// BepuPhysics 2 (built by the user and referenced with -p:BepuDir=...): its substepping solver
    /// with SolveDescription(iterations, substeps), sleeping off; Timestep on the calling thread, or
    /// with Bepu's own ThreadDispatcher for more threads.
    /// </summary>
    public sealed class BepuPeer : IPeerEngine
    {
        readonly int _threads;
        ThreadDispatcher? _dispatcher;
        BufferPool? _pool;
        Simulation? _simulation;
        BepuBodyHandle[] _bodies = System.Array.Empty<BepuBodyHandle>();

        /// <summary>A Bepu row on <paramref name="threads"/> threads.</summary>
        public BepuPeer(int threads = 1) => _threads = threads;

        public string Name => "Bepu2" + (_threads > 1 ? $" {_threads} threads" : "");

        public int Threads => _threads;

        public string Version => PeerRoster.VersionOf(typeof(Simulation));

        public void Build(PeerScene scene, PeerSettings settings)
        {
            _pool = new BufferPool();
            if (_threads > 1) _dispatcher = new ThreadDispatcher(_threads);
            var contacts = new BepuContactCallbacks(settings.Friction, settings.MaxPushSpeed,
                new SpringSettings(settings.ContactHertz, settings.ContactDampingRatio));
            var gravity = new BepuGravityCallbacks(new Vector3(0, settings.GravityY, 0));
            _simulation = Simulation.Create(_pool, contacts, gravity, new SolveDescription(settings.Iterations, settings.Substeps));

            Vector3 g = 2 * scene.Ground.HalfExtents;
            _simulation.Statics.Add(new StaticDescription(scene.Ground.Center, _simulation.Shapes.Add(new Box(g.X, g.Y, g.Z))));

            // A negative sleep threshold can never be reached by a squared speed: no sleeping.
            var awake = new BodyActivityDescription(-1);
            _bodies = new BepuBodyHandle[scene.Boxes.Count];
            Box shape = default;
            TypedIndex index = default;
            for (int i = 0; i < _bodies.Length; i++)
            {
                PeerBox box = scene.Boxes[i];
                Vector3 size = 2 * box.HalfExtents;
                // Equal boxes share one shape, as a Bepu user would write it.
                if (i == 0 || size != new Vector3(shape.Width, shape.Height, shape.Length))
                {
                    shape = new Box(size.X, size.Y, size.Z);
                    index = _simulation.Shapes.Add(shape);
                }
                _bodies[i] = _simulation.Bodies.Add(BodyDescription.CreateDynamic(
                    new RigidPose(box.Center, box.Rotation), shape.ComputeInertia(settings.BoxMass), new CollidableDescription(index), awake));
            }
        }

        public void Step(float dt) => _simulation!.Timestep(dt, _dispatcher);

        public void ReadPose(int box, out Vector3 position, out Quaternion rotation)
        {
            RigidPose pose = _simulation!.Bodies[_bodies[box]].Pose;
            position = pose.Position;
            rotation = pose.Orientation;
        }

        public void Dispose()
        {
            _simulation?.Dispose();
            _pool?.Clear();
            _dispatcher?.Dispose();
            _simulation = null;
            _pool = null;
            _dispatcher = null;
        }
    }
}
#endif
