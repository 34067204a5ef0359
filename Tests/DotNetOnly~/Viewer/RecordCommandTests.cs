using System;
using System.IO;
using System.Net.Http;
using System.Threading;
using System.Threading.Tasks;
using Fulcrum.Runner;
using NUnit.Framework;

namespace Fulcrum.Tests.Viewer
{
    /// <summary><c>fulcrum run --record</c> and <c>fulcrum view</c>.</summary>
    public class RecordCommandTests : Scenes.RunnerSession
    {
        [Test]
        public void Run_with_record_writes_frame_0_every_kth_step_and_the_last()
        {
            string path = Path.Combine(Dir, "sub", "tower.frec");
            var (code, output, error) = Fulcrum("run", Scene("tower-10"), "--steps", "25", "--every", "10", "--record", path);
            Assert.That(code, Is.EqualTo(Cli.ExitOk), error);
            Assert.That(output, Does.Contain("recording: " + path + ", 4 frames"));
            Recording rec = Recording.Read(File.ReadAllBytes(path));
            Assert.That(rec.Frames.ConvertAll(f => f.Step), Is.EqualTo(new long[] { 0, 10, 20, 25 }));
            Assert.That(rec.Bodies, Has.Count.EqualTo(11));
            Assert.That(rec.Bodies[1].Name, Is.EqualTo("tower/0"), "scene names");
        }

        [Test]
        public void Run_with_record_of_a_soft_scene_records_vertices_and_element_J()
        {
            string path = Path.Combine(Dir, "jelly.frec");
            var (code, _, error) = Fulcrum("run", Scene("jelly-stack"), "--steps", "5", "--record", path);
            Assert.That(code, Is.EqualTo(Cli.ExitOk), error);
            Recording rec = Recording.Read(File.ReadAllBytes(path));
            Assert.That(rec.SoftBodies.ConvertAll(s => s.Name), Is.EqualTo(new[] { "bottom", "middle", "top" }));
            Assert.That(rec.Frames, Has.Count.EqualTo(6));
            Assert.That(rec.Frames[5].SoftElementJ[0], Has.All.GreaterThan(0.5f).And.LessThan(1.5f));
        }

        [Test]
        public void A_bad_record_flag_writes_nothing()
        {
            var (code, _, error) = Fulcrum("run", Scene("tower-10"), "--steps", "5", "--record", Dir);
            Assert.That(code, Is.EqualTo(Cli.ExitUsage));
            Assert.That(error, Does.Contain("--record: '" + Dir + "' is a directory"));
            (code, _, error) = Fulcrum("run", Scene("tower-10"), "--every", "2");
            Assert.That(error, Does.Contain("--every: only applies with --trace or --record"));
        }

        [Test]
        public void View_refuses_a_file_that_is_not_a_recording()
        {
            string path = Path.Combine(Dir, "x.frec");
            File.WriteAllText(path, "hello");
            var (code, _, error) = Fulcrum("view", path, "--viewer", Dir);
            Assert.That(code, Is.EqualTo(Cli.ExitScene));
            Assert.That(error, Does.Contain("not a Fulcrum recording"));
        }

        [Test]
        public async Task View_serves_the_viewer_and_the_recording_and_nothing_else()
        {
            string viewer = Path.Combine(Dir, "dist");
            Directory.CreateDirectory(Path.Combine(viewer, "assets"));
            File.WriteAllText(Path.Combine(viewer, "index.html"), "<html>viewer</html>");
            File.WriteAllText(Path.Combine(viewer, "assets", "app.js"), "console.log(1)");
            File.WriteAllText(Path.Combine(Dir, "secret.txt"), "no");
            string rec = Path.Combine(Dir, "tower.frec");
            Assert.That(Fulcrum("run", Scene("tower-10"), "--steps", "2", "--record", rec).code, Is.EqualTo(0));

            int port = 20000 + Random.Shared.Next(20000);
            using var stop = new CancellationTokenSource();
            var output = new StringWriter();
            TextWriter shared = TextWriter.Synchronized(output);
            string Text() { lock (shared) return output.ToString(); }
            Task<int> server = Task.Run(() => ViewCommand.Run(
                new Arguments("view", new[] { "view", rec, "--port", port.ToString(), "--viewer", viewer }, 1, ViewCommand.Flags), shared, stop.Token));
            // No request before the server says it serves: .NET's managed HttpListener starts its
            // first accept before it has made the table that accept files the connection in, and
            // a connection that lands in between crashes the whole test host (a null lock on a
            // pool thread; CI once lost 24 tests to it, from this test's retry loop).
            var deadline = DateTime.UtcNow.AddSeconds(30);
            while (!Text().Contains("serving http") && DateTime.UtcNow < deadline && !server.IsCompleted) await Task.Delay(20);
            using var http = new HttpClient { BaseAddress = new Uri($"http://127.0.0.1:{port}/") };
            string index = "";
            for (int attempt = 0; attempt < 50 && index.Length == 0; attempt++)
            {
                try { index = await http.GetStringAsync("/"); }
                catch (HttpRequestException) { await Task.Delay(100); }
            }
            try
            {
                Assert.That(index, Is.EqualTo("<html>viewer</html>"));
                HttpResponseMessage js = await http.GetAsync("/assets/app.js");
                Assert.That(js.Content.Headers.ContentType?.MediaType, Is.EqualTo("text/javascript"));
                byte[] served = await http.GetByteArrayAsync(ViewCommand.RecordingPath);
                Assert.That(served, Is.EqualTo(File.ReadAllBytes(rec)));
                Assert.That((int)(await http.GetAsync("/../secret.txt")).StatusCode, Is.EqualTo(404));
                Assert.That((int)(await http.GetAsync("/%2e%2e/secret.txt")).StatusCode, Is.EqualTo(404));
                Assert.That(Text(), Does.Contain($"serving http://127.0.0.1:{port}/?file=recording.frec&name=tower.frec"));
            }
            finally
            {
                stop.Cancel();
                Assert.That(await server, Is.EqualTo(Cli.ExitOk));
            }
        }
    }
}
