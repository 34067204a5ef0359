using System;
using System.Numerics;
using Fulcrum.Dynamics;

namespace Fulcrum.Components
{
    public sealed partial class HingeJoint
    {
        bool _useSpring;
        JointSpring _spring;

        /// <summary>Whether <see cref="spring"/> acts. Default: false.</summary>
        public bool useSpring
        {
            get => _useSpring;
            set { ThrowIfStepping(nameof(useSpring)); _useSpring = value; PushSpring(); }
        }

        /// <summary>
        /// The spring toward <see cref="JointSpring.targetPosition"/>, in Unity's units (used
        /// when <see cref="useSpring"/>). Fulcrum's hinge spring is implicit (a soft constraint
        /// given as a frequency and damping ratio, stable at any stiffness): the stiffness and
        /// damper are turned into those with the effective inertia about the axis when the joint
        /// is built or the spring set, so the spring is exactly Unity's at that pose and close to
        /// it as the bodies turn. A target other than the build angle adds the constant torque
        /// stiffness × target, which moves the spring's rest angle there.
        /// </summary>
        public JointSpring spring
        {
            get => _spring;
            set
            {
                if (!(float.IsFinite(value.spring) && value.spring >= 0)) throw new ArgumentException($"{this}: spring.spring must be finite and >= 0, got {value.spring}.", nameof(spring));
                if (!(float.IsFinite(value.damper) && value.damper >= 0)) throw new ArgumentException($"{this}: spring.damper must be finite and >= 0, got {value.damper}.", nameof(spring));
                if (!(value.targetPosition >= -180 && value.targetPosition <= 180)) throw new ArgumentException($"{this}: spring.targetPosition must be in [-180, 180] degrees, got {value.targetPosition}.", nameof(spring));
                ThrowIfStepping(nameof(spring));
                _spring = value;
                PushSpring();
            }
        }

        /// <summary>The angular speed of this body relative to the connected one about the axis, degrees/s (Unity's HingeJoint.velocity).</summary>
        public float velocity
        {
            get
            {
                if (!IsBuilt) return 0f;
                World w = scene.world;
                JointSpringMath.Ends(w, joint, out int a, out int b);
                BodyStorage s = w.Bodies;
                Vector3 wa = a < 0 ? Vector3.Zero : s.AngularVelocity[a];
                Vector3 wb = b < 0 ? Vector3.Zero : s.AngularVelocity[b];
                return Vector3.Dot(wb - wa, WorldAxis()) * (180f / MathF.PI);
            }
        }

        void ConfigureSpring(ref JointDef def)
        {
            if (!_useSpring || _spring.spring <= 0) return;
            World w = scene.world;
            Vector3 n = w.GetBody(def.BodyB).Pose.TransformDirection(Vector3.Normalize(axis));
            int a = def.BodyA.IsNone ? -1 : def.BodyA.Index;
            JointSpringMath.ToFrequency(w.Bodies, a, def.BodyB.Index, n, _spring, out def.StiffnessHz, out def.Damping);
        }

        void PushSpring()
        {
            if (!IsBuilt) return;
            World w = scene.world;
            ref JointData j = ref w.Joints.Data[joint.Index];
            if (_useSpring && _spring.spring > 0)
                JointSpringMath.ToFrequency(w.Bodies, j.BodyA, j.BodyB, WorldAxis(), _spring, out j.SpringHertz, out j.SpringDamping);
            else
                j.SpringHertz = j.SpringDamping = 0;
            if (j.BodyA >= 0) w.Bodies.Awake[j.BodyA] = true;
            if (j.BodyB >= 0) w.Bodies.Awake[j.BodyB] = true;
        }

        /// <summary>True when the spring has a target away from the build angle: the scene applies <see cref="ApplySpringTarget"/> before each step.</summary>
        internal bool HasSpringTarget => _useSpring && _spring.spring > 0 && _spring.targetPosition != 0 && IsBuilt;

        /// <summary>
        /// The constant part of the spring torque k (θ - θt) = kθ - kθt: the solver's implicit
        /// spring supplies kθ (toward the build angle), this adds kθt on this body about the
        /// axis and its opposite on the connected one. Bodies at rest stay asleep.
        /// </summary>
        internal void ApplySpringTarget()
        {
            World w = scene.world;
            JointSpringMath.Ends(w, joint, out int a, out int b);
            BodyStorage s = w.Bodies;
            if (!(a >= 0 && s.Awake[a]) && !(b >= 0 && s.Awake[b])) return;
            Vector3 torque = WorldAxis() * (_spring.spring * _spring.targetPosition * (MathF.PI / 180f));
            // B is this entity's body and A the connected one (Joint.TryBuild).
            Rigidbody? own = entity.GetComponent<Rigidbody>();
            Rigidbody? other = connectedBody;
            if (b >= 0 && s.Type[b] == BodyType.Dynamic && own != null && own.HasBody) w.AddTorque(own.body, torque);
            if (a >= 0 && s.Type[a] == BodyType.Dynamic && other != null && other.HasBody) w.AddTorque(other.body, -torque);
        }

        Vector3 WorldAxis()
        {
            ref JointData j = ref scene.world.Joints.Data[joint.Index];
            Quaternion q = j.BodyB < 0 ? Quaternion.Identity : scene.world.Bodies.Rotation[j.BodyB];
            return Vector3.Normalize(Vector3.Transform(axis, q));
        }
    }

    /// <summary>Unity's hinge spring (N m/rad, N m s/rad) as Fulcrum's soft-constraint frequency and damping ratio.</summary>
    internal static class JointSpringMath
    {
        /// <summary>The body slots of a joint's two ends (-1 for the world).</summary>
        public static void Ends(World w, JointHandle joint, out int a, out int b)
        {
            ref JointData j = ref w.Joints.Data[joint.Index];
            a = j.BodyA;
            b = j.BodyB;
        }

        /// <summary>
        /// The effective inertia about <paramref name="n"/> is I = 1 / (n·IA⁻¹n + n·IB⁻¹n); a
        /// spring k on it oscillates at ω = √(k/I), and a damper c has damping ratio
        /// ζ = c / (2√(kI)). Both ends fixed (no inertia): no spring.
        /// </summary>
        public static void ToFrequency(BodyStorage s, int a, int b, Vector3 n, in JointSpring spring, out float hertz, out float ratio)
        {
            float inverse = 0;
            if (a >= 0 && s.Type[a] == BodyType.Dynamic) inverse += Vector3.Dot(n, s.InverseInertiaWorld[a] * n);
            if (b >= 0 && s.Type[b] == BodyType.Dynamic) inverse += Vector3.Dot(n, s.InverseInertiaWorld[b] * n);
            if (!(inverse > 0)) { hertz = ratio = 0; return; }
            float inertia = 1f / inverse;
            float omega = MathF.Sqrt(spring.spring / inertia);
            hertz = omega / (2f * MathF.PI);
            ratio = spring.damper / (2f * MathF.Sqrt(spring.spring * inertia));
        }
    }
}
