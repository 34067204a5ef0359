using System;
using System.Collections.Generic;
using System.IO;
using System.Text;
using Fulcrum.Scenes;
using NUnit.Framework;

namespace Fulcrum.Tests.Validation
{
    /// <summary>
    /// A small seeded fuzz of the scene reader: truncated files, every value replaced by each
    /// wrong type or a hostile number, and huge nesting. Reading must only ever report
    /// <see cref="SceneError"/>s with a path (never a NullReference, IndexOutOfRange or stack
    /// overflow), and a scene that passes must build or be refused with a SceneException.
    /// </summary>
    public class SceneFuzzTests
    {
        static readonly string[] Scenes = { "chain", "bullet", "box-on-jelly", "wall", "dominoes", "pinned-flag", "jelly-seesaw", "jelly-on-mesh-ramp", "bridge" };

        static readonly string[] Replacements =
        {
            "\"s\"", "[]", "{}", "null", "true", "[1]", "[1, 2, 3, 4, 5]", "-1e39", "1e38", "3e38", "-0", "2147483648",
            "-2147483649", "1e-45", "0", "-1", "1e13", "[1e20, 1e20, 1e20]", "[0, 0, 0, 0]", "{\"x\": 1}",
        };

        static string ScenesDir() => PackageRoot.ScenesDirectory;

        static int _built;

        // Reads (and, when valid, builds) one text; anything but scene errors fails the test.
        static void Probe(string text, string what)
        {
            IReadOnlyList<SceneError> errors;
            SceneDocument? doc;
            try
            {
                errors = SceneFile.Check(text, out doc);
            }
            catch (Exception e)
            {
                Assert.Fail($"{what}: Check threw {e.GetType().Name}: {SceneError.Clip(e.Message, 200)}");
                return;
            }
            foreach (SceneError err in errors)
            {
                Assert.That(err.Path, Does.StartWith("$"), what);
                Assert.That(err.ToString(), Does.Not.Contain("\n"), what);
            }
            if (errors.Count > 0 || doc == null) return;
            try
            {
                SceneInstance scene = SceneBuilder.Build(doc, WorldSettings.Default);
                if (scene.SoftBodies.Count > 0) Fulcrum.SoftBodies.SceneSoftBodyBuilder.Build(scene, directory: ScenesDir());
                _built++;
                scene.World.Step(doc.Timestep);
            }
            catch (SceneException e)
            {
                Assert.That(e.Errors[0].Path, Does.StartWith("$"), what);
            }
            catch (Exception e)
            {
                Assert.Fail($"{what}: Build threw {e.GetType().Name}: {SceneError.Clip(e.Message, 200)}");
            }
        }

        // The start offsets and lengths of every number and every string value (not member names) in a JSON text.
        static List<(int start, int length)> Values(string text)
        {
            var list = new List<(int, int)>();
            for (int i = 0; i < text.Length; i++)
            {
                char c = text[i];
                if (c == '"')
                {
                    int end = text.IndexOf('"', i + 1);
                    if (end < 0) break;
                    int next = end + 1;
                    while (next < text.Length && char.IsWhiteSpace(text[next])) next++;
                    if (next >= text.Length || text[next] != ':') list.Add((i, end - i + 1));
                    i = end;
                }
                else if (c == '-' || char.IsDigit(c))
                {
                    int end = i;
                    while (end < text.Length && "+-.eE0123456789".IndexOf(text[end]) >= 0) end++;
                    list.Add((i, end - i));
                    i = end - 1;
                }
            }
            return list;
        }

        [Test]
        public void Wrong_types_and_hostile_numbers_at_every_value_give_only_scene_errors()
        {
            var random = new Random(11);
            int cases = 0;
            _built = 0;
            foreach (string name in Scenes)
            {
                string text = File.ReadAllText(Path.Combine(ScenesDir(), name + ".json"));
                List<(int start, int length)> values = Values(text);
                foreach ((int start, int length) in values)
                {
                    // Every value with a few replacements (seeded), so each path sees each kind over the suite.
                    for (int k = 0; k < 5; k++)
                    {
                        string r = Replacements[random.Next(Replacements.Length)];
                        Probe(text.Substring(0, start) + r + text.Substring(start + length), $"{name}: offset {start} -> {r}");
                        cases++;
                    }
                }
            }
            TestContext.Out.WriteLine($"{cases} mutated scenes, {_built} of them valid and built");
            Assert.That(cases, Is.GreaterThan(1000));
        }

        [Test]
        public void Truncated_files_give_only_scene_errors()
        {
            int cases = 0;
            foreach (string name in Scenes)
            {
                string text = File.ReadAllText(Path.Combine(ScenesDir(), name + ".json"));
                int stride = Math.Max(1, text.Length / 150);
                for (int n = 0; n < text.Length; n += stride, cases++) Probe(text.Substring(0, n), $"{name}: first {n} characters");
            }
            Assert.That(cases, Is.GreaterThan(500));
        }

        [TestCase("[", "]")]
        [TestCase("{\"a\":", "}")]
        [TestCase("{\"bodies\": [", "]}")]
        public void Huge_nesting_is_refused_without_overflowing_the_stack(string open, string close)
        {
            var sb = new StringBuilder();
            for (int i = 0; i < 100_000; i++) sb.Append(open);
            sb.Append('1');
            for (int i = 0; i < 100_000; i++) sb.Append(close);
            IReadOnlyList<SceneError> errors = SceneFile.Check(sb.ToString(), out _);
            // errors.Count, not Has.Count: NUnit 3.5/3.6 look Count up on the runtime type (an array here) and miss it.
            Assert.That(errors.Count, Is.EqualTo(1));
            Assert.That(errors[0].Message, Does.Contain("nesting deeper than " + JsonParser.MaxDepth));
        }
    }
}
