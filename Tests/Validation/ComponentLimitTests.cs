using System;
using System.Numerics;
using Fulcrum.Components;
using NUnit.Framework;

namespace Fulcrum.Tests.Validation
{
    /// <summary>The components check the same limits as the World, at the call (not when a deferred value is applied).</summary>
    public class ComponentLimitTests
    {
        [Test]
        public void Rigidbody_and_collider_values_beyond_the_limits_are_refused_at_the_call()
        {
            var scene = new PhysicsScene(WorldSettings.Default, 0.25f);
            var rb = scene.CreateEntity("Ball").AddComponent<Rigidbody>();
            Assert.That(() => rb.mass = 1e-38f, Throws.ArgumentException.With.Message.Contains("Limits.MinMass/MaxMass"));
            Assert.That(rb.mass, Is.EqualTo(1f));
            Assert.That(() => rb.angularVelocity = new Vector3(3e38f), Throws.ArgumentException.With.Message.Contains("Limits.MaxInputSpeed"));
            Assert.That(() => rb.position = new Vector3(0, 3e38f, 0), Throws.ArgumentException.With.Message.Contains("Limits.MaxPosition"));
            Assert.That(() => rb.AddTorque(new Vector3(3e38f)), Throws.ArgumentException.With.Message.Contains("Limits.MaxForce"));
            Assert.That(rb.angularVelocity, Is.EqualTo(Vector3.Zero));
            var sphere = scene.CreateEntity("Orb").AddComponent<SphereCollider>();
            Assert.That(() => sphere.radius = 1e20f, Throws.ArgumentException.With.Message.Contains("Limits.MinShapeSize/MaxShapeSize"));
        }
    }
}
