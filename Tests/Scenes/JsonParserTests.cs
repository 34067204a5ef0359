using Fulcrum.Scenes;
using NUnit.Framework;

namespace Fulcrum.Tests.Scenes
{
    public class JsonParserTests
    {
        static SceneError ErrorOf(string text)
        {
            var e = Assert.Throws<SceneException>(() => JsonParser.Parse(text))!;
            Assert.That(e.Errors.Count, Is.EqualTo(1));
            return e.Errors[0];
        }

        [Test]
        public void Every_value_knows_its_path_line_and_column()
        {
            JsonValue root = JsonParser.Parse("{\n  \"a\": [1,\n    {\"b c\": true}]\n}");
            JsonValue inner = root["a"]!.Items[1]["b c"]!;
            Assert.That(inner.Path, Is.EqualTo("$.a[1][\"b c\"]"));
            Assert.That(inner.Line, Is.EqualTo(3));
            Assert.That(inner.Column, Is.EqualTo(13));
            Assert.That(root["a"]!.Items[0].NumberText, Is.EqualTo("1"));
        }

        [Test]
        public void A_missing_comma_is_reported_at_its_line_and_column_with_the_enclosing_path()
        {
            SceneError e = ErrorOf("{\n  \"bodies\": [\n    {\"name\": \"a\" \"shape\": 1}\n  ]\n}");
            Assert.That(e.Path, Is.EqualTo("$.bodies[0]"));
            Assert.That(e.Line, Is.EqualTo(3));
            Assert.That(e.Column, Is.EqualTo(18));
            Assert.That(e.ToString(), Is.EqualTo("$.bodies[0]: unexpected '\"', expected ',' or '}' (line 3, column 18)"));
        }

        [TestCase("{\"a\": 1,}", "$", 1, 9)]
        [TestCase("[1, 2", "$", 1, 6)]
        [TestCase("{\"a\": 01}", "$.a", 1, 8)]
        [TestCase("{\"a\": .5}", "$.a", 1, 7)]
        [TestCase("{\"a\": tru}", "$.a", 1, 7)]
        [TestCase("{\"a\": \"x\ny\"}", "$.a", 1, 9)]
        [TestCase("{\"a\": 1} x", "$", 1, 10)]
        [TestCase("{\"a\": 1, \"a\": 2}", "$.a", 1, 10)]
        [TestCase("", "$", 1, 1)]
        public void Malformed_json_names_the_path_line_and_column(string text, string path, int line, int column)
        {
            SceneError e = ErrorOf(text);
            Assert.That((e.Path, e.Line, e.Column), Is.EqualTo((path, line, column)), e.ToString());
        }

        [Test]
        public void Escapes_decode_and_quote_back()
        {
            JsonValue v = JsonParser.Parse("\"a\\\"b\\\\c\\n\\u00e9\\/\"");
            Assert.That(v.AsString, Is.EqualTo("a\"b\\c\né/"));
            Assert.That(JsonPath.Quote(v.AsString), Is.EqualTo("\"a\\\"b\\\\c\\né/\""));
        }

        [Test]
        public void Hostile_nesting_is_an_error_not_a_stack_overflow()
        {
            SceneError e = ErrorOf(new string('[', 10000));
            Assert.That(e.Message, Does.Contain("nesting deeper"));
        }
    }
}
