using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    // The world side of the bridge: whatever thread steps the world (the game thread, or the
    // physics thread) owns these fields and runs these methods.
    public sealed partial class PhysicsBridge
    {
        BodyHandle[] _wBody = new BodyHandle[16];
        int[] _wGeneration = new int[16];
        IPhysicsEntity?[] _wEntity = new IPhysicsEntity?[16];
        DriveMode[] _wMode = new DriveMode[16];
        bool[] _wHaptics = new bool[16];
        Pose[] _wFrom = new Pose[16];
        Pose[] _wTo = new Pose[16];
        bool[] _wHasTarget = new bool[16];
        int _wSlotCount;
        int[] _proxyOfBody = Array.Empty<int>();        // body slot -> proxy slot
        int[] _proxyBodyGeneration = Array.Empty<int>(); // body generation it was mapped for
        int[] _releaseAfterStep = new int[16];
        BodyHandle[] _releaseBody = new BodyHandle[16]; // the destroyed body of each, whose body slot may be reused at once
        int _releaseAfterStepCount;
        readonly BridgeContactBatch _wEvents = new BridgeContactBatch();
        ContactEvent[] _injected = new ContactEvent[16];
        int _injectedCount;

        // Shared: slots the world side has finished with, handed back to the game side (under _sync).
        int[] _released = new int[16];
        int _releasedCount;

        /// <summary>Queues a contact event to be resolved after the next step (tests; no physics thread).</summary>
        internal void InjectContactEvent(in ContactEvent e)
        {
            if (_threaded) throw new InvalidOperationException("InjectContactEvent is for bridges without a physics thread.");
            if (_injectedCount == _injected.Length) Array.Resize(ref _injected, _injected.Length * 2);
            _injected[_injectedCount++] = e;
        }

        void ApplyCommands(BridgeCommandQueue q)
        {
            for (int k = 0; k < q.Count; k++) Apply(q, ref q.Items[k]);
            q.Clear();
        }

        void Apply(BridgeCommandQueue q, ref BridgeCommand c)
        {
            int slot = c.Slot;
            if (c.Kind == BridgeCommandKind.Create)
            {
                Create(q, ref c);
                return;
            }
            if (slot >= _wSlotCount || _wGeneration[slot] != c.Generation || _wBody[slot].IsNone) return;
            BodyHandle body = _wBody[slot];
            switch (c.Kind)
            {
                case BridgeCommandKind.Destroy:
                    _world.DestroyBody(body);
                    _wBody[slot] = default;
                    _wHasTarget[slot] = false;
                    if (_releaseAfterStepCount == _releaseAfterStep.Length)
                    {
                        Array.Resize(ref _releaseAfterStep, _releaseAfterStep.Length * 2);
                        Array.Resize(ref _releaseBody, _releaseAfterStep.Length);
                    }
                    _releaseBody[_releaseAfterStepCount] = body;
                    _releaseAfterStep[_releaseAfterStepCount++] = slot;
                    break;
                case BridgeCommandKind.SetMode:
                    _world.SetBodyType(body, c.Mode == DriveMode.Game ? BodyType.Kinematic : BodyType.Dynamic);
                    _wMode[slot] = c.Mode;
                    _wHasTarget[slot] = false;
                    break;
                case BridgeCommandKind.AddForce:
                    _world.AddForce(body, c.Vector, c.ForceMode);
                    break;
                case BridgeCommandKind.AddForceAtPosition:
                    _world.AddForceAtPosition(body, c.Vector, c.Point, c.ForceMode);
                    break;
                case BridgeCommandKind.AddTorque:
                    _world.AddTorque(body, c.Vector, c.ForceMode);
                    break;
                case BridgeCommandKind.SetLinearVelocity:
                    _world.GetBody(body).LinearVelocity = c.Vector;
                    break;
                case BridgeCommandKind.SetAngularVelocity:
                    _world.GetBody(body).AngularVelocity = c.Vector;
                    break;
                case BridgeCommandKind.Teleport:
                {
                    BodyRef r = _world.GetBody(body);
                    r.Position = c.Vector;
                    r.Rotation = c.Rotation;
                    _wHasTarget[slot] = false;
                    break;
                }
                case BridgeCommandKind.SetHaptics:
                    _wHaptics[slot] = c.Flag;
                    break;
            }
        }

        void Create(BridgeCommandQueue q, ref BridgeCommand c)
        {
            int slot = c.Slot;
            EnsureWorldSlots(slot + 1);
            BodyHandle body = _world.CreateBody(c.Body);
            for (int s = 0; s < c.ShapeCount; s++) _world.AddShape(body, q.Shapes[c.ShapeStart + s]);
            _wBody[slot] = body;
            _wGeneration[slot] = c.Generation;
            _wEntity[slot] = c.Entity;
            _wMode[slot] = c.Mode;
            _wHaptics[slot] = false;
            _wHasTarget[slot] = false;
            if (body.Index >= _proxyOfBody.Length)
            {
                int n = Math.Max(16, Math.Max(body.Index + 1, _proxyOfBody.Length * 2));
                int old = _proxyOfBody.Length;
                Array.Resize(ref _proxyOfBody, n);
                Array.Resize(ref _proxyBodyGeneration, n);
                for (int i = old; i < n; i++) _proxyOfBody[i] = -1;
            }
            _proxyOfBody[body.Index] = slot;
            _proxyBodyGeneration[body.Index] = body.Generation;
        }

        void EnsureWorldSlots(int count)
        {
            if (count > _wBody.Length)
            {
                int n = Math.Max(count, _wBody.Length * 2);
                Array.Resize(ref _wBody, n);
                Array.Resize(ref _wGeneration, n);
                Array.Resize(ref _wEntity, n);
                Array.Resize(ref _wMode, n);
                Array.Resize(ref _wHaptics, n);
                Array.Resize(ref _wFrom, n);
                Array.Resize(ref _wTo, n);
                Array.Resize(ref _wHasTarget, n);
            }
            if (count > _wSlotCount) _wSlotCount = count;
        }

        // Sets the game poses just read as the targets of the coming steps, starting from where
        // each body is now (game thread, no physics thread).
        void TakeInputs()
        {
            for (int slot = 0; slot < _gSlots.SlotCount; slot++)
            {
                if (_gState[slot] != Live || _gMode[slot] != DriveMode.Game || _gStatic[slot]) continue;
                if (slot >= _wSlotCount || _wGeneration[slot] != _gSlots.Generation[slot] || _wBody[slot].IsNone) continue;
                SetTarget(slot, _gInput[slot]);
            }
        }

        // The game's pose becomes the target of the coming steps of a game-driven body, which
        // StepWorld moves there from where the body is now (TakeInputs, TakeSharedInputs).
        void SetTarget(int slot, in Pose to)
        {
            _wFrom[slot] = _world.GetBody(_wBody[slot]).Pose;
            _wTo[slot] = to;
            _wHasTarget[slot] = true;
        }

        // One world step: the k-th of n this frame. Game-driven bodies get a kinematic target a
        // (k+1)/n of the way to the game's pose, so a frame's motion spreads over its steps.
        void StepWorld(float dt, int k, int n)
        {
            float t = (k + 1) / (float)n;
            for (int slot = 0; slot < _wSlotCount; slot++)
            {
                if (!_wHasTarget[slot] || _wBody[slot].IsNone || _wMode[slot] != DriveMode.Game) continue;
                Pose from = _wFrom[slot], to = _wTo[slot];
                _world.SetKinematicTarget(_wBody[slot], Vector3.Lerp(from.Position, to.Position, t), Quaternion.Slerp(from.Rotation, to.Rotation, t));
                if (k == n - 1) _wHasTarget[slot] = false; // consumed: without a new pose the body stops
            }
            _world.Step(dt);
            RecordStep();
            ResolveEvents(dt);
            ReleaseSlots();
        }

        void ResolveEvents(float dt)
        {
            ReadOnlySpan<ContactEvent> events = WorldEvents.Of(_world);
            for (int k = 0; k < events.Length; k++) Resolve(events[k], dt);
            for (int k = 0; k < _injectedCount; k++) Resolve(_injected[k], dt);
            _injectedCount = 0;
        }

        void Resolve(in ContactEvent e, float dt)
        {
            int a = ProxySlotOf(e.BodyA), b = ProxySlotOf(e.BodyB);
            if (a < 0 && b < 0) return;
            ref BridgeContact c = ref _wEvents.AddContact();
            c.Kind = e.Kind;
            c.IsTrigger = e.IsSensor;
            c.ProxyA = a < 0 ? default : new ProxyHandle(a, _wGeneration[a], _world.Id);
            c.ProxyB = b < 0 ? default : new ProxyHandle(b, _wGeneration[b], _world.Id);
            c.EntityA = a < 0 ? null : _wEntity[a];
            c.EntityB = b < 0 ? null : _wEntity[b];
            c.Normal = e.Normal;
            c.Point = e.Point;
            c.PointCount = e.PointCount;
            c.NormalImpulse = e.NormalImpulse;
            c.RelativeVelocity = e.RelativeVelocity;
            c.StepIndex = _world.StepIndex;
            c.Time = _world.Time;
            c.FirstPoint = _wEvents.PointCount;
            c.StoredPoints = e.Kind == ContactEventKind.End || e.IsSensor ? 0 : StorePoints(e);
            if (Haptics != null && !e.IsSensor && ((a >= 0 && _wHaptics[a]) || (b >= 0 && _wHaptics[b])))
            {
                Haptics.Write(new ContactForceSample
                {
                    Time = c.Time,
                    StepIndex = c.StepIndex,
                    Kind = e.Kind,
                    ProxyA = c.ProxyA,
                    ProxyB = c.ProxyB,
                    Point = e.Point,
                    Normal = e.Normal,
                    Force = e.Kind == ContactEventKind.End ? Vector3.Zero : e.Normal * (e.NormalImpulse / dt),
                    RelativeVelocity = e.RelativeVelocity,
                });
            }
        }

        // Copies the points of the pair's manifolds after the event's; returns how many.
        int StorePoints(in ContactEvent e)
        {
            if (!_world.IsValid(e.ShapeA) || !_world.IsValid(e.ShapeB)) return 0;
            ContactGraph g = _world.ContactGraph;
            int k = g.Find(e.ShapeA.Index, e.ShapeB.Index);
            if (k < 0) return 0;
            int n = 0;
            for (int m = g.Contacts[k].FirstManifold; m >= 0; m = g.ManifoldNext[m])
            {
                ref ContactManifold mf = ref g.Manifolds[m];
                for (int i = 0; i < mf.PointCount; i++)
                {
                    ref Fulcrum.Collision.ContactPoint p = ref ContactManifold.Point(ref mf, i);
                    _wEvents.AddPoint(new BridgeContactPoint { Position = p.Position, Normal = mf.Normal, Separation = p.Separation, NormalImpulse = p.AppliedImpulse });
                    n++;
                }
            }
            return n;
        }

        int ProxySlotOf(BodyHandle body)
        {
            if (body.IsNone) return -1;
            if ((uint)body.Index >= (uint)_proxyOfBody.Length) return DyingSlotOf(body);
            int slot = _proxyOfBody[body.Index];
            if (slot >= 0 && _proxyBodyGeneration[body.Index] == body.Generation) return slot;
            return DyingSlotOf(body);
        }

        // A body destroyed since the last step: its slot in the world may already hold a new body.
        int DyingSlotOf(BodyHandle body)
        {
            for (int k = 0; k < _releaseAfterStepCount; k++)
                if (_releaseBody[k] == body) return _releaseAfterStep[k];
            return -1;
        }

        // Slots whose bodies were destroyed before this step have had their end events
        // resolved: the game side may reuse them now.
        void ReleaseSlots()
        {
            if (_releaseAfterStepCount == 0) return;
            lock (_sync)
            {
                for (int k = 0; k < _releaseAfterStepCount; k++)
                {
                    int slot = _releaseAfterStep[k];
                    _wEntity[slot] = null;
                    _wGeneration[slot] = 0;
                    if (_releasedCount == _released.Length) Array.Resize(ref _released, _released.Length * 2);
                    _released[_releasedCount++] = slot;
                }
            }
            _releaseAfterStepCount = 0;
        }

        // Game side: takes back the slots the world side released.
        void ReclaimReleasedSlots()
        {
            lock (_sync)
            {
                for (int k = 0; k < _releasedCount; k++)
                {
                    int slot = _released[k];
                    _gState[slot] = Free;
                    _gEntity[slot] = null;
                    _gSlots.Release(slot);
                }
                _releasedCount = 0;
            }
        }
    }
}
