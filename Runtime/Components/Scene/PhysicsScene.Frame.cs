using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    public sealed partial class PhysicsScene
    {
        float _frameDt;
        bool _inFixedPhase;
        bool _inTick;

        /// <summary>
        /// Runs one frame of <paramref name="frameDt"/> seconds in Unity's order:
        /// pending Starts; then for each fixed step the frame calls for (zero or more):
        /// FixedUpdate on every enabled behaviour, transforms edited by user code pushed to
        /// their bodies, <see cref="World.Step"/>, body poses written back to the transforms,
        /// OnTrigger* then OnCollision* messages; then the transforms of interpolated bodies
        /// blended for rendering, Update, LateUpdate, and the destroys requested during the frame.
        /// Allocates nothing in steady state.
        /// </summary>
        public void Tick(float frameDt)
        {
            FieldCheck.NonNegative(frameDt, "PhysicsScene.Tick", nameof(frameDt));
            ThrowIfReentered("Tick");
            _inTick = true;
            try
            {
                _frameDt = frameDt;
                RunStarts();
                int steps = _stepper.Consume(frameDt);
                for (int s = 0; s < steps; s++)
                {
                    _inFixedPhase = true;
                    RunFixedUpdates();
                    StepAndDispatch(_stepper.FixedDt);
                    _inFixedPhase = false;
                    RunStarts();
                }
                ShowInterpolatedPoses(_stepper.InterpolationFactor);
                RunStarts();
                RunUpdates();
                RunLateUpdates();
                ProcessDestroys();
                time += frameDt;
                frameCount++;
            }
            finally
            {
                _inTick = false;
                _inFixedPhase = false;
            }
        }

        /// <summary>
        /// One physics step of <paramref name="dt"/> seconds without the behaviour messages
        /// around it (for hosts that call FixedUpdate themselves, such as the Unity adapter):
        /// transforms edited by user code are pushed to their bodies, the world steps, poses
        /// are written back to the transforms and the collision and trigger messages are sent.
        /// Destroys requested by those messages run when it returns.
        /// </summary>
        public void Simulate(float dt)
        {
            ThrowIfReentered("Simulate");
            _inTick = true;
            try
            {
                _inFixedPhase = true;
                StepAndDispatch(dt);
            }
            finally
            {
                _inFixedPhase = false;
                _inTick = false;
            }
            ProcessDestroys();
        }

        /// <summary>
        /// Writes each body's pose to its transform for rendering at <paramref name="alpha"/>
        /// (0 = the previous step, 1 = the last one): bodies with
        /// <see cref="RigidbodyInterpolation.Interpolate"/> blend the two step poses, those with
        /// Extrapolate run ahead of the last pose by alpha steps of their velocity, and the others
        /// show the last step.
        /// </summary>
        public void ShowInterpolatedPoses(float alpha)
        {
            if (!float.IsFinite(alpha)) throw new ArgumentException($"alpha must be finite, got {alpha}.", nameof(alpha));
            // The step last taken: a host calling Simulate with its own step (Unity's
            // Time.fixedDeltaTime, which a game may change) extrapolates by that one.
            float dt = _lastStepDt > 0 ? _lastStepDt : _stepper.FixedDt;
            BodyStorage b = _world.Bodies;
            for (int k = 0; k < _rigidbodies.Count; k++)
            {
                Rigidbody rb = _rigidbodies[k];
                if (!rb.HasBody || rb.transform.HierarchyVersion != rb.SeenTransformVersion) continue;
                switch (rb.interpolation)
                {
                    case RigidbodyInterpolation.Interpolate:
                        rb.WriteTransform(_world.GetInterpolatedPose(rb.body, alpha));
                        break;
                    case RigidbodyInterpolation.Extrapolate:
                    {
                        int i = rb.body.Index;
                        float ahead = Math.Clamp(alpha, 0f, 1f) * dt;
                        // Extrapolate the centre of mass, then place the origin from the new rotation.
                        Quaternion q = Rotation.Integrate(b.Rotation[i], b.AngularVelocity[i], ahead);
                        Vector3 c = b.Center[i] + b.LinearVelocity[i] * ahead;
                        rb.WriteTransform(new Pose(c - Vector3.Transform(b.LocalCenter[i], q), q));
                        break;
                    }
                    default:
                        rb.WriteTransform(_world.GetBody(rb.body).Pose);
                        break;
                }
            }
        }

        float _lastStepDt;

        void StepAndDispatch(float dt)
        {
            _lastStepDt = dt;
            PushEditedTransforms();
            BuildPendingJoints();
            BeforeStepConstraints();
            _world.Step(dt);
            AfterStep();
            RecordStep();
            DispatchMessages();
            DispatchJointBreaks();
        }

        // Transforms that user code moved since the host last wrote them teleport their bodies
        // (Unity's transform sync before the simulation).
        void PushEditedTransforms()
        {
            for (int k = 0; k < _rigidbodies.Count; k++)
            {
                Rigidbody rb = _rigidbodies[k];
                if (!rb.HasBody) continue;
                long v = rb.transform.HierarchyVersion;
                if (v == rb.SeenTransformVersion) continue;
                Pose p = rb.transform.WorldPose;
                BodyRef r = _world.GetBody(rb.body);
                r.Position = p.Position;
                r.Rotation = p.Rotation;
                rb.SeenTransformVersion = v;
            }
            for (int k = 0; k < _colliders.Count; k++)
            {
                Collider c = _colliders[k];
                if (c.HasShape && c.TransformChanged) c.Rebuild();
            }
        }

        void BeforeStepConstraints()
        {
            for (int k = 0; k < _joints.Count; k++)
                if (_joints[k] is HingeJoint h && !h.isDestroyed && h.HasSpringTarget) h.ApplySpringTarget();
            BodyStorage b = _world.Bodies;
            for (int k = 0; k < _rigidbodies.Count; k++)
            {
                Rigidbody rb = _rigidbodies[k];
                if (!rb.HasBody || rb.isKinematic) continue;
                if (rb.HasSpeedCaps) rb.ClampSpeeds(b, rb.body.Index);
            }
        }

        void AfterStep()
        {
            BodyStorage b = _world.Bodies;
            for (int k = 0; k < _rigidbodies.Count; k++)
            {
                Rigidbody rb = _rigidbodies[k];
                if (!rb.HasBody) continue;
                int i = rb.body.Index;
                if (rb.HasSpeedCaps && !rb.isKinematic) rb.ClampSpeeds(b, i);
                rb.WriteTransform(new Pose(b.Position[i], b.Rotation[i]));
            }
        }

        void RunStarts()
        {
            // Start may enable more behaviours; they join the queue and run in this pass.
            for (int k = 0; k < _startQueue.Count; k++)
            {
                Behaviour b = _startQueue[k];
                b.StartQueued = false;
                if (b.Started || b.isDestroyed) continue;
                if (!b.isActiveAndEnabled) continue; // started when next enabled
                b.RunStart();
            }
            _startQueue.Clear();
        }

        void RunFixedUpdates()
        {
            int n = _behaviours.Count;
            for (int k = 0; k < n; k++)
            {
                Behaviour b = _behaviours[k];
                if (b.Started && b.isActiveAndEnabled) b.RunFixedUpdate();
            }
        }

        void RunUpdates()
        {
            int n = _behaviours.Count;
            for (int k = 0; k < n; k++)
            {
                Behaviour b = _behaviours[k];
                if (b.Started && b.isActiveAndEnabled) b.RunUpdate();
            }
        }

        void RunLateUpdates()
        {
            int n = _behaviours.Count;
            for (int k = 0; k < n; k++)
            {
                Behaviour b = _behaviours[k];
                if (b.Started && b.isActiveAndEnabled) b.RunLateUpdate();
            }
        }

        void ThrowIfReentered(string what)
        {
            if (_dispatching != null)
                throw new InvalidOperationException($"PhysicsScene.{what} was called from {_dispatching}: a scene cannot step from inside its own physics messages.");
            if (_inTick)
                throw new InvalidOperationException($"PhysicsScene.{what} was called from inside Tick or Simulate (from a behaviour message): a scene cannot step from inside its own frame.");
            if (_world.IsStepping)
                throw new InvalidOperationException($"PhysicsScene.{what} was called while the world steps (from a callback inside World.Step).");
        }
    }
}
