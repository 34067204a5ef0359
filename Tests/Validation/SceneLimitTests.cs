using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text;
using Fulcrum.Scenes;
using NUnit.Framework;

namespace Fulcrum.Tests.Validation
{
    /// <summary>
    /// Hostile scene files and runner flags get one line naming the field (JSON path) or flag,
    /// never a stack trace, an overflow, a hang or an out-of-memory read (issue 11, item 4).
    /// </summary>
    public partial class SceneLimitTests
    {
        const string Head = "\"format\": \"fulcrum-scene/1\", \"gravity\": [0, -9.81, 0], \"timestep\": 0.0166667, \"solver\": { \"type\": \"tgs\", \"iterations\": 4, \"substeps\": 4 }";
        string _dir = "";

        [SetUp]
        public void MakeTempDir()
        {
            _dir = Path.Combine(Path.GetTempPath(), "fulcrum-limits-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_dir);
        }

        [TearDown]
        public void RemoveTempDir() => Directory.Delete(_dir, recursive: true);

        static SceneError FirstError(string json)
        {
            IReadOnlyList<SceneError> errors = SceneFile.Check(json, out _);
            Assert.That(errors, Is.Not.Empty, "the scene should be refused");
            return errors[0];
        }

        string Write(string name, string text)
        {
            string path = Path.Combine(_dir, name);
            File.WriteAllText(path, text);
            return path;
        }

        [TestCase("{ \"type\": \"box\", \"halfExtents\": [1e20, 1, 1] }", "$.bodies[0].shape.halfExtents")]
        [TestCase("{ \"type\": \"sphere\", \"radius\": 1e6 }", "$.bodies[0].shape.radius")]
        [TestCase("{ \"type\": \"capsule\", \"radius\": 1, \"halfHeight\": 1e30 }", "$.bodies[0].shape.halfHeight")]
        [TestCase("{ \"type\": \"compound\", \"children\": [{ \"shape\": { \"type\": \"sphere\", \"radius\": 1 }, \"position\": [1e9, 0, 0] }] }", "$.bodies[0].shape.children[0].position")]
        public void Shapes_beyond_the_API_limits_are_refused_with_their_path(string shape, string path)
        {
            string json = "{" + Head + ", \"bodies\": [{ \"name\": \"b\", \"type\": \"dynamic\", \"shape\": " + shape + " }] }";
            Assert.That(FirstError(json).Path, Is.EqualTo(path));
        }

        [TestCase("\"position\": [0, 3e38, 0]", "$.bodies[0].position")]
        [TestCase("\"velocity\": [3e38, 0, 0]", "$.bodies[0].velocity")]
        [TestCase("\"angularVelocity\": [0, 0, 3e38]", "$.bodies[0].angularVelocity")]
        [TestCase("\"mass\": 1e-38", "$.bodies[0].mass")]
        public void Body_fields_the_API_would_refuse_are_refused_by_the_validator(string field, string path)
        {
            string json = "{" + Head + ", \"bodies\": [{ \"name\": \"b\", \"type\": \"dynamic\", \"shape\": { \"type\": \"sphere\", \"radius\": 1 }, " + field + " }] }";
            Assert.That(FirstError(json).Path, Is.EqualTo(path));
        }

        [Test]
        public void Timestep_and_solver_counts_are_capped()
        {
            Assert.That(FirstError("{\"format\": \"fulcrum-scene/1\", \"timestep\": 1e-30, \"bodies\": []}").Path, Is.EqualTo("$.timestep"));
            Assert.That(FirstError("{\"format\": \"fulcrum-scene/1\", \"timestep\": 1e6, \"bodies\": []}").Path, Is.EqualTo("$.timestep"));
            Assert.That(FirstError("{\"format\": \"fulcrum-scene/1\", \"timestep\": 0.01, \"solver\": {\"type\": \"tgs\", \"iterations\": 4, \"substeps\": 1000000000}, \"bodies\": []}").Path,
                Is.EqualTo("$.solver.substeps"));
        }

        [TestCase("{ \"type\": \"pyramid\", \"count\": 2147483647, \"size\": [1, 1, 1], \"at\": [0, 0, 0] }")]
        [TestCase("{ \"type\": \"pile\", \"grid\": [2147483647, 2147483647, 2147483647], \"size\": [1, 1, 1], \"at\": [0, 0, 0] }")]
        [TestCase("{ \"type\": \"wall\", \"count\": 2, \"rows\": 2147483647, \"size\": [1, 1, 1], \"at\": [0, 0, 0] }")]
        public void Generator_counts_that_overflow_are_checked_against_the_body_cap(string generator)
        {
            var watch = Stopwatch.StartNew();
            SceneError e = FirstError("{" + Head + ", \"bodies\": [], \"generators\": [" + generator + "] }");
            Assert.That(e.Path, Is.EqualTo("$.generators[0]"));
            Assert.That(e.Message, Does.Contain("more than 1000000 bodies"));
            Assert.That(watch.Elapsed.TotalSeconds, Is.LessThan(2));
        }

        [Test]
        public void A_hull_of_100k_points_is_refused_in_the_file_and_the_API()
        {
            var sb = new StringBuilder("{" + Head + ", \"bodies\": [{ \"name\": \"h\", \"type\": \"dynamic\", \"shape\": { \"type\": \"convex\", \"points\": [");
            for (int i = 0; i < 100_000; i++) sb.Append(i == 0 ? "" : ",").Append($"[{i % 7}, {i / 7 % 7}, {i}]");
            sb.Append("] } }] }");
            SceneError e = FirstError(sb.ToString());
            Assert.That(e.Path, Is.EqualTo("$.bodies[0].shape.points"));
            Assert.That(e.Message, Does.Contain("Limits.MaxHullPoints"));
            var points = new System.Numerics.Vector3[Limits.MaxHullPoints + 1];
            for (int i = 0; i < points.Length; i++) points[i] = new System.Numerics.Vector3(i % 7, i / 7 % 7, i);
            Assert.That(() => ConvexHull.Create(points), Throws.ArgumentException.With.Message.Contains("Limits.MaxHullPoints"));
        }

        [Test]
        public void Two_hundred_thousand_keys_are_refused_fast_and_duplicates_found_in_linear_time()
        {
            var sb = new StringBuilder("{");
            for (int i = 0; i < 200_000; i++) sb.Append(i == 0 ? "" : ",").Append($"\"k{i}\": 1");
            sb.Append('}');
            var watch = Stopwatch.StartNew();
            SceneError e = FirstError(sb.ToString());
            Assert.That(e.Message, Does.Contain($"more than {JsonParser.MaxMembers} members"));
            // Below the cap, the duplicate check is a hash set: 10k keys and a duplicate at the end.
            sb.Clear().Append('{');
            for (int i = 0; i < JsonParser.MaxMembers - 1; i++) sb.Append($"\"k{i}\": 1,");
            sb.Append("\"k5\": 2}");
            e = FirstError(sb.ToString());
            Assert.That(e.Path, Is.EqualTo("$.k5"));
            Assert.That(e.Message, Does.Contain("duplicate"));
            Assert.That(watch.Elapsed.TotalSeconds, Is.LessThan(2));
        }

        [Test]
        public void A_huge_number_or_string_is_not_echoed_whole()
        {
            string digits = "1" + new string('0', 5_000_000);
            SceneError e = FirstError("{\"format\": \"fulcrum-scene/1\", \"timestep\": " + digits + ", \"bodies\": []}");
            Assert.That(e.Path, Is.EqualTo("$.timestep"));
            Assert.That(e.ToString().Length, Is.LessThan(200));
            Assert.That(e.Message, Does.Contain("..."));
            e = FirstError("{\"format\": \"fulcrum-scene/1\", \"timestep\": 0.01, \"bodies\": [{\"name\": \"" + new string('x', 100_000) + "\"}]}");
            Assert.That(e.ToString().Length, Is.LessThan(300));
            // Short but out of range: clipped to 40 characters too.
            e = FirstError("{\"format\": \"fulcrum-scene/1\", \"timestep\": 1e99999999999999999999999999999999999999999999999999, \"bodies\": []}");
            Assert.That(e.Message, Does.Contain("..."));
        }
    }
}
