using System;
using System.Collections.Generic;
using System.Numerics;
using Fulcrum.Scenes;
using NUnit.Framework;

namespace Fulcrum.Tests.Scenes
{
    public class SceneGeneratorTests
    {
        static readonly Vector3 At = new Vector3(2, 1.5f, -3);

        static IEnumerable<TestCaseData> Generators()
        {
            yield return new TestCaseData(new SceneTower { Count = 7, At = At, Size = new Vector3(1, 0.5f, 2), Spacing = 0.05f }, 7).SetName("Tower");
            yield return new TestCaseData(new ScenePyramid { Count = 5, At = At, Axis = SceneAxis.Z, Size = new Vector3(1, 0.7f, 0.5f), Spacing = 0.1f }, 15).SetName("Pyramid");
            yield return new TestCaseData(new SceneWall { Count = 4, Rows = 5, At = At }, 4 + 3 + 4 + 3 + 4).SetName("Wall_staggered");
            yield return new TestCaseData(new SceneWall { Count = 3, Rows = 2, At = At, Staggered = false, Axis = SceneAxis.Z }, 6).SetName("Wall_straight");
            yield return new TestCaseData(new ScenePile { Grid = new[] { 3, 2, 4 }, At = At }, 24).SetName("Pile_of_boxes");
            yield return new TestCaseData(new ScenePile { Grid = new[] { 2, 3, 2 }, At = At, Shape = SceneShapeType.Sphere, Spacing = 0 }, 12).SetName("Pile_of_spheres");
            yield return new TestCaseData(new ScenePile { Grid = new[] { 2, 2, 2 }, At = At, Shape = SceneShapeType.Capsule, Size = new Vector3(0.5f, 1.5f, 0.5f) }, 8).SetName("Pile_of_capsules");
            yield return new TestCaseData(new SceneChain { Count = 6, At = At, Spacing = 0.1f }, 6).SetName("Chain");
            yield return new TestCaseData(new SceneDominoes { Count = 9, At = At, Axis = SceneAxis.Z, TipSpeed = 1 }, 9).SetName("Dominoes");
        }

        static (Vector3 min, Vector3 max) Bounds(SceneBody b)
        {
            Assert.That(b.Rotation, Is.EqualTo(Quaternion.Identity), "generators make axis-aligned bodies");
            Vector3 h = b.Shape switch
            {
                SceneBox box => box.HalfExtents,
                SceneSphere s => new Vector3(s.Radius),
                SceneCapsule c => new Vector3(c.Radius, c.HalfHeight + c.Radius, c.Radius),
                _ => throw new AssertionException("unexpected shape " + b.Shape),
            };
            return (b.Position - h, b.Position + h);
        }

        [TestCaseSource(nameof(Generators))]
        public void Expands_to_the_documented_count_named_by_type_and_index(SceneGenerator g, int count)
        {
            var bodies = new List<SceneBody>();
            g.Expand(bodies, new List<SceneJoint>());
            Assert.That(bodies.Count, Is.EqualTo(count));
            Assert.That(g.BodyCount, Is.EqualTo(count));
            for (int i = 0; i < count; i++) Assert.That(bodies[i].Name, Is.EqualTo(SceneNames.Of(g.Type) + "/" + i));
            g.Name = "mine";
            bodies.Clear();
            g.Expand(bodies, new List<SceneJoint>());
            Assert.That(bodies[count - 1].Name, Is.EqualTo("mine/" + (count - 1)));
        }

        [TestCaseSource(nameof(Generators))]
        public void Rests_on_the_ground_plane_at_y_without_any_overlap(SceneGenerator g, int count)
        {
            var bodies = new List<SceneBody>();
            g.Expand(bodies, new List<SceneJoint>());
            const float eps = 1e-5f;
            float lowest = float.MaxValue;
            for (int i = 0; i < bodies.Count; i++)
            {
                (Vector3 min, Vector3 max) = Bounds(bodies[i]);
                lowest = MathF.Min(lowest, min.Y);
                Assert.That(min.Y, Is.GreaterThanOrEqualTo(At.Y - eps), bodies[i].Name);
                for (int j = 0; j < i; j++)
                {
                    (Vector3 min2, Vector3 max2) = Bounds(bodies[j]);
                    Vector3 overlap = Vector3.Min(max, max2) - Vector3.Max(min, min2);
                    bool overlaps = overlap.X > eps && overlap.Y > eps && overlap.Z > eps;
                    Assert.That(overlaps, Is.False, $"{bodies[i].Name} overlaps {bodies[j].Name} by {overlap}");
                }
            }
            Assert.That(lowest, Is.EqualTo(At.Y).Within(eps), "the lowest bodies touch the ground");
            Assert.That(bodies[0].Position.Y, Is.EqualTo(lowest + (Bounds(bodies[0]).max.Y - Bounds(bodies[0]).min.Y) / 2).Within(eps), "body 0 is at the bottom");
        }

        [Test]
        public void Tower_boxes_each_rest_on_the_one_below()
        {
            var tower = new SceneTower { Count = 20, At = At, Size = new Vector3(1, 0.3f, 1) };
            var bodies = new List<SceneBody>();
            tower.Expand(bodies, new List<SceneJoint>());
            for (int i = 1; i < bodies.Count; i++)
                Assert.That(Bounds(bodies[i]).min.Y, Is.EqualTo(Bounds(bodies[i - 1]).max.Y).Within(1e-5f));
            Assert.That(bodies[19].Position, Is.EqualTo(new Vector3(At.X, At.Y + 0.3f * 19.5f, At.Z)).Using(new VectorTolerance(1e-5f)));
        }

        [Test]
        public void Chain_joints_join_neighbours_at_a_shared_world_point()
        {
            var chain = new SceneChain { Count = 4, At = At, Spacing = 0.2f, Anchor = SceneChainAnchor.Both, Axis = SceneAxis.Z };
            var bodies = new List<SceneBody>();
            var joints = new List<SceneJoint>();
            chain.Expand(bodies, joints);
            Assert.That(joints.Count, Is.EqualTo(chain.JointCount).And.EqualTo(5));
            var byName = new Dictionary<string, SceneBody>();
            foreach (SceneBody b in bodies) byName.Add(b.Name, b);
            Vector3 World(string? body, Vector3 anchor) => body == null ? anchor : byName[body].Position + anchor;
            for (int i = 0; i < joints.Count; i++)
            {
                SceneJoint j = joints[i];
                Assert.That(j, Is.TypeOf<SceneBallJoint>());
                Assert.That(j.Name, Is.EqualTo("chain/" + i));
                Assert.That(World(j.BodyA, j.AnchorA), Is.EqualTo(World(j.BodyB, j.AnchorB)).Using(new VectorTolerance(1e-5f)), j.Name);
            }
            Assert.That(joints[0].BodyB, Is.Null, "anchored to the world at the start");
            Assert.That(joints[0].AnchorB, Is.EqualTo(At + new Vector3(0, 0.1f, 0)).Using(new VectorTolerance(1e-6f)));
            Assert.That((joints[1].BodyA, joints[1].BodyB), Is.EqualTo(("chain/0", "chain/1")));
            Assert.That(joints[4].BodyB, Is.Null, "and at the end");
        }

        [Test]
        public void First_domino_turns_about_its_leading_bottom_edge()
        {
            var dominoes = new SceneDominoes { Count = 3, At = At, TipSpeed = 2 };
            var bodies = new List<SceneBody>();
            dominoes.Expand(bodies, new List<SceneJoint>());
            SceneBody first = bodies[0];
            Vector3 pivot = new Vector3(At.X + 0.05f, At.Y, At.Z);
            Vector3 pivotVelocity = first.Velocity + Vector3.Cross(first.AngularVelocity, pivot - first.Position);
            Assert.That(pivotVelocity.Length(), Is.EqualTo(0).Within(1e-6f));
            Assert.That(first.AngularVelocity, Is.EqualTo(new Vector3(0, 0, -2)), "top moves toward +x");
            Assert.That(bodies[1].Velocity, Is.EqualTo(Vector3.Zero));
            Assert.That(bodies[1].Position.X - first.Position.X, Is.EqualTo(0.5f).Within(1e-6f), "thickness 0.1 + gap 0.4");
        }
    }

    /// <summary>Vector equality within an absolute tolerance per component.</summary>
    sealed class VectorTolerance : IEqualityComparer<Vector3>
    {
        readonly float _tol;
        public VectorTolerance(float tol) => _tol = tol;
        public bool Equals(Vector3 a, Vector3 b) => MathF.Abs(a.X - b.X) <= _tol && MathF.Abs(a.Y - b.Y) <= _tol && MathF.Abs(a.Z - b.Z) <= _tol;
        public int GetHashCode(Vector3 v) => 0;
    }
}
