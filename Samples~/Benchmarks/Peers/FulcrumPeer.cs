using System.Numerics;

namespace Fulcrum.Benchmarks.Peers
{
    /// <summary>
    /// Fulcrum itself, TGS with the matched substeps and iterations; optionally on more threads
    /// (its worker pool) or with manifold reuse off (every touching pair runs its pair function
    /// every step, as in the other engines).
    /// </summary>
    public sealed class FulcrumPeer : IPeerEngine
    {
        readonly int _threads;
        readonly bool _reuse;
        World? _world;
        BodyHandle[] _bodies = System.Array.Empty<BodyHandle>();

        /// <summary>A Fulcrum row on <paramref name="threads"/> threads, with or without manifold reuse.</summary>
        public FulcrumPeer(int threads = 1, bool reuse = true)
        {
            _threads = threads;
            _reuse = reuse;
        }

        public string Name => "Fulcrum" + (_reuse ? "" : " reuse off") + (_threads > 1 ? $" {_threads} threads" : "");

        public int Threads => _threads;

        public string Version => PeerRoster.VersionOf(typeof(World));

        public void Build(PeerScene scene, PeerSettings settings)
        {
            WorldSettings ws = WorldSettings.Default;
            ws.Solver = SolverType.Tgs;
            ws.Substeps = settings.Substeps;
            ws.Iterations = settings.Iterations;
            ws.RelaxIterations = settings.RelaxIterations;
            ws.Gravity = new Vector3(0, settings.GravityY, 0);
            ws.ContactHertz = settings.ContactHertz;
            ws.ContactDampingRatio = settings.ContactDampingRatio;
            ws.MaxContactPushSpeed = settings.MaxPushSpeed;
            ws.EnableSleeping = false;
            ws.Threads = _threads;
            if (!_reuse) ws.ManifoldReuseDistance = 0;
            var world = new World(ws);

            BodyHandle ground = world.CreateBody(BodyDef.Static(scene.Ground.Center));
            world.AddShape(ground, Box(scene.Ground.HalfExtents, settings.Friction));

            _bodies = new BodyHandle[scene.Boxes.Count];
            for (int i = 0; i < _bodies.Length; i++)
            {
                PeerBox box = scene.Boxes[i];
                BodyDef def = BodyDef.Dynamic(box.Center);
                def.Rotation = box.Rotation;
                def.Mass = settings.BoxMass;
                def.AllowSleep = false;
                _bodies[i] = world.CreateBody(def);
                world.AddShape(_bodies[i], Box(box.HalfExtents, settings.Friction));
            }
            // Capacity for the scene up front, as Bepu's pools get their initial allocation
            // sizes: a collapsing pile then allocates nothing while its contact count rises.
            world.Reserve(scene.Boxes.Count + 1, 8 * scene.Boxes.Count);
            _world = world;
        }

        static ShapeDef Box(Vector3 halfExtents, float friction)
        {
            ShapeDef shape = ShapeDef.Of(ShapeGeometry.Box(halfExtents));
            shape.Friction = friction;
            return shape;
        }

        public void Step(float dt) => _world!.Step(dt);

        /// <summary>The per-stage times of the last step (World.LastStepProfile).</summary>
        public StepProfile LastStepProfile => _world!.LastStepProfile;

        public void ReadPose(int box, out Vector3 position, out Quaternion rotation)
        {
            BodyRef body = _world!.GetBody(_bodies[box]);
            position = body.Position;
            rotation = body.Rotation;
        }

        public void Dispose()
        {
            _world?.StopThreads();
            _world = null;
        }
    }
}
