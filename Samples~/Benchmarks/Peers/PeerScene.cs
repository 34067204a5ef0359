using System;
using System.Collections.Generic;
using System.Numerics;

namespace Fulcrum.Benchmarks.Peers
{
    /// <summary>
    /// An engine-neutral scene: a static ground box whose top face is y = 0 and a list of dynamic
    /// boxes of equal mass. Every engine builds the same list, so initial conditions match exactly.
    /// </summary>
    public sealed class PeerScene
    {
        /// <summary>Scene name printed in the table.</summary>
        public string Name { get; }
        /// <summary>The static ground (top face at y = 0).</summary>
        public PeerBox Ground { get; }
        /// <summary>The dynamic boxes, in creation order.</summary>
        public IReadOnlyList<PeerBox> Boxes { get; }
        /// <summary>Index of the box whose drift and sink are reported, or -1 for none.</summary>
        public int Tracked { get; }
        /// <summary>Steps run before timing starts (JIT, caches, first contacts).</summary>
        public int WarmupSteps { get; }
        /// <summary>Steps run after warm-up: up to the end of the last phase (steps between phases run untimed).</summary>
        public int MeasuredSteps { get; }
        /// <summary>
        /// The timed steps split into consecutive phases, each reported as its own row (a pile's
        /// collapse and its settled heap cost differently; one figure over both hides either).
        /// The accuracy figures of a phase are read after its last step.
        /// </summary>
        public IReadOnlyList<PeerPhase> Phases { get; }

        PeerScene(string name, List<PeerBox> boxes, int tracked, int warmupSteps, params PeerPhase[] phases)
        {
            Name = name;
            Ground = new PeerBox(new Vector3(0, -0.5f, 0), Quaternion.Identity, new Vector3(100, 0.5f, 100));
            Boxes = boxes;
            Tracked = tracked;
            WarmupSteps = warmupSteps;
            Phases = phases;
            int steps = 0;
            foreach (PeerPhase phase in phases) steps = Math.Max(steps, phase.Start + phase.Steps);
            MeasuredSteps = steps;
        }

        PeerScene(string name, List<PeerBox> boxes, int tracked, int warmupSteps, int measuredSteps)
            : this(name, boxes, tracked, warmupSteps, new PeerPhase(name, 0, measuredSteps))
        {
        }

        static readonly Vector3 Half = new Vector3(0.5f);

        /// <summary>A column of unit cubes standing on the ground, just touching.</summary>
        public static PeerScene Tower(int count, int warmupSteps, int measuredSteps)
        {
            var boxes = new List<PeerBox>(count);
            for (int i = 0; i < count; i++)
                boxes.Add(new PeerBox(new Vector3(0, 0.5f + i, 0), Quaternion.Identity, Half));
            return new PeerScene($"tower {count}", boxes, count - 1, warmupSteps, measuredSteps);
        }

        /// <summary>
        /// A square 3D pyramid of unit cubes: layer k holds (baseSize - k)^2 boxes, each resting on
        /// four below it. A 5 cm gap between neighbours in a layer keeps side faces out of contact.
        /// </summary>
        public static PeerScene Pyramid(int baseSize, int warmupSteps, int measuredSteps)
        {
            const float pitch = 1.05f;
            var boxes = new List<PeerBox>();
            for (int layer = 0; layer < baseSize; layer++)
            {
                int n = baseSize - layer;
                float start = -0.5f * (n - 1) * pitch;
                for (int i = 0; i < n; i++)
                    for (int k = 0; k < n; k++)
                        boxes.Add(new PeerBox(new Vector3(start + i * pitch, 0.5f + layer, start + k * pitch), Quaternion.Identity, Half));
            }
            return new PeerScene($"pyramid {baseSize}", boxes, boxes.Count - 1, warmupSteps, measuredSteps);
        }

        /// <summary>
        /// Boxes in a loose grid (side x side columns, 1.5 m apart, layers 1.5 m apart from 1 m up),
        /// each tilted by a small seeded random rotation so the columns collapse into a pile.
        /// One phase of <paramref name="measuredSteps"/> timed steps.
        /// </summary>
        public static PeerScene Pile(int side, int layers, int warmupSteps, int measuredSteps) =>
            new PeerScene($"pile {side * side * layers}", PileBoxes(side, layers), -1, warmupSteps, measuredSteps);

        /// <summary>
        /// The same pile timed in two phases: <paramref name="collapseSteps"/> steps while it
        /// falls and collapses, then, after <paramref name="untimedSteps"/> untimed steps (still
        /// stepped, not measured), <paramref name="settledSteps"/> steps of the heap at rest.
        /// </summary>
        public static PeerScene PilePhases(int side, int layers, int warmupSteps, int collapseSteps, int untimedSteps, int settledSteps)
        {
            string name = $"pile {side * side * layers}";
            return new PeerScene(name, PileBoxes(side, layers), -1, warmupSteps,
                new PeerPhase(name + " collapse", 0, collapseSteps),
                new PeerPhase(name + " settled", collapseSteps + untimedSteps, settledSteps));
        }

        static List<PeerBox> PileBoxes(int side, int layers)
        {
            const float pitch = 1.5f;
            var random = new Random(12345);
            var boxes = new List<PeerBox>(side * side * layers);
            float start = -0.5f * (side - 1) * pitch;
            for (int layer = 0; layer < layers; layer++)
                for (int i = 0; i < side; i++)
                    for (int k = 0; k < side; k++)
                    {
                        var axis = Vector3.Normalize(new Vector3(
                            (float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f) + new Vector3(1e-3f));
                        var tilt = Quaternion.CreateFromAxisAngle(axis, 0.3f * (float)random.NextDouble());
                        boxes.Add(new PeerBox(new Vector3(start + i * pitch, 1f + layer * pitch, start + k * pitch), tilt, Half));
                    }
            return boxes;
        }
    }
}
