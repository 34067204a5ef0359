using System;
using System.IO;
using Fulcrum.Collision;
using Fulcrum.Dynamics;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    public sealed partial class World
    {
        /// <summary>
        /// Writes everything a step reads to <paramref name="stream"/>: settings, bodies, shapes
        /// (hulls and meshes included), joints with their accumulated impulses, the broad-phase
        /// trees, contacts and manifolds with their impulses and reuse data, sleep timers and
        /// islands, pending events, and the soft bodies' state. Saving, restoring (into this world
        /// or a fresh one, in this process or another) and stepping on gives bit for bit the
        /// steps that never stopping gives. The format is binary and versioned; see
        /// <see cref="RestoreState"/> for what it accepts. Not during a step.
        /// </summary>
        public void SaveState(Stream stream)
        {
            if (stream == null) throw new ArgumentNullException(nameof(stream));
            ThrowIfInStep();
            var w = new StateWriter();
            var stage = SoftBodyStage as IStateStage;
            bool withStage = stage != null && stage.HasState;

            w.Section("WRLD");
            w.Write(_settings);
            w.Write(_stepIndex);
            w.Write(Time);
            w.Write(DivergenceCount);
            w.Write(LastDivergence.Body.Index);
            w.Write(LastDivergence.Body.Generation);
            w.Write(LastDivergence.Step);
            w.Write(LastDivergence.Kind);
            w.Write(_ccdShapeCount);
            Bodies.Save(w);
            Shapes.Save(w);
            Joints.Save(w);
            _broadPhase.Save(w);
            ContactGraph.Save(w);

            w.Section("IGNR");
            IgnoredPairs.Save(w);
            w.WriteArray(IgnoredPairList.ToArray());

            w.Section("STEP");
            w.WritePool(Contacts.Source, Contacts.ManifoldCount);
            w.WriteArray(_shapeMotion);
            w.WriteArray(_shapeRadius);
            w.WriteArray(_shapePose);
            w.WriteArray(_shapePoseStep);
            w.WriteArray(_fatBoxStep);
            w.WriteArray(_islands.SleepNext);
            w.WritePool(_removalEvents, _removalEventCount);

            w.Section("SOFT");
            w.Write(withStage);
            if (withStage) stage!.SaveState(w);
            w.Section("END!");
            StateFile.Write(stream, w, withStage ? StateLayout.Hash(stage!.LayoutTypes) : 0);
        }

        /// <summary>
        /// Replaces this world's state with one written by <see cref="SaveState"/>: every body,
        /// shape, joint and contact is the saved one (handles issued before the save name the same
        /// objects again; handles of objects created since are stale), and the settings are the
        /// saved ones. Soft bodies are not created from the state: a state with soft bodies needs
        /// the same soft bodies to exist already (build the same scene first); their positions,
        /// velocities and pins come from the state. All or nothing: a state that is truncated,
        /// damaged (checksum), from another format version or data layout, or that does not fit
        /// this world's soft bodies throws <see cref="InvalidDataException"/> and changes nothing.
        /// <see cref="ContactEvents"/> is empty until the next step. Not during a step.
        /// </summary>
        public void RestoreState(Stream stream)
        {
            if (stream == null) throw new ArgumentNullException(nameof(stream));
            ThrowIfInStep();
            byte[] bytes = StateFile.Read(stream, out int start, out int end, out ulong stageLayout);
            var r = new StateReader(bytes, start, end);

            r.Section("WRLD");
            var settings = r.Read<WorldSettings>("settings");
            try { settings.Validate(); }
            catch (ArgumentException e) { throw r.Error("the saved settings are invalid: " + e.Message); }
            long stepIndex = r.Read<long>("step index");
            double time = r.Read<double>("time");
            int divergences = r.Read<int>("divergence count");
            var lastDivergence = new Divergence(new BodyHandle(r.Read<int>("divergence body"), r.Read<int>("divergence generation"), Id),
                r.Read<long>("divergence step"), r.Read<DivergenceKind>("divergence kind"));
            int ccdShapes = r.Read<int>("CCD shape count");
            BodyStorage bodies = BodyStorage.Load(r);
            ShapeStorage shapes = ShapeStorage.Load(r);
            JointStorage joints = JointStorage.Load(r, bodies.SlotCount);
            BroadPhase broadPhase = Collision.BroadPhase.Load(r);
            ContactGraph graph = ContactGraph.Load(r);
            CheckLinks(r, bodies, shapes, graph);

            r.Section("IGNR");
            PairMap ignored = PairMap.Load(r, 1);
            ulong[] ignoredList = r.ReadArray<ulong>("ignored pairs");
            if (ignoredList.Length != ignored.Count) throw r.Error($"{ignoredList.Length} ignored pairs listed, {ignored.Count} in the map.");
            foreach (ulong key in ignoredList)
            {
                int a = (int)(key >> 32), b = (int)(uint)key;
                if (a < 0 || a >= b || b >= shapes.SlotCount || ignored.Find(key) < 0)
                    throw r.Error($"an ignored pair names shapes {a} and {b} of {shapes.SlotCount}.");
            }

            r.Section("STEP");
            int[] source = r.ReadPool<int>("step manifolds", out int manifoldCount);
            foreach (int m in new ReadOnlySpan<int>(source, 0, manifoldCount))
                if ((uint)m >= (uint)graph.Manifolds.Length) throw r.Error($"a step manifold names pool entry {m} of {graph.Manifolds.Length}.");
            float[] shapeMotion = r.ReadArray<float>("shape motion");
            float[] shapeRadius = r.ReadArrayExactly<float>("shape radii", shapeMotion.Length);
            Pose[] shapePose = r.ReadArrayExactly<Pose>("shape poses", shapeMotion.Length);
            long[] shapePoseStep = r.ReadArrayExactly<long>("shape pose steps", shapeMotion.Length);
            long[] fatBoxStep = r.ReadArrayExactly<long>("shape bound steps", shapeMotion.Length);
            if (shapeMotion.Length < shapes.SlotCount) throw r.Error($"per-shape arrays of {shapeMotion.Length} entries for {shapes.SlotCount} shape slots.");
            int[] sleepNext = r.ReadArray<int>("sleep rings");
            foreach (int next in sleepNext)
                if (next < -1 || next >= bodies.SlotCount) throw r.Error($"a sleep ring links to body slot {next} of {bodies.SlotCount}.");
            ContactEvent[] removals = r.ReadPool<ContactEvent>("pending end events", out int removalCount);

            r.Section("SOFT");
            bool hasStage = r.Read<bool>("soft-body flag");
            Action? commitStage = null;
            var stage = SoftBodyStage as IStateStage;
            if (hasStage)
            {
                if (stage == null)
                    throw r.Error("the state holds soft bodies but this world has none: create the same soft bodies (build the same scene) before restoring.");
                if (StateLayout.Hash(stage.LayoutTypes) != stageLayout)
                    throw r.Error("the soft bodies were saved by a build whose soft-body data layout differs from this one.");
                commitStage = stage.PrepareRestore(r);
            }
            else if (stage != null && stage.HasState)
                throw r.Error("the state holds no soft bodies but this world has some: restore into a world built without them.");
            r.Section("END!");
            if (!r.AtEnd) throw r.Error("bytes follow the end of the state.");

            // Everything was read and checked: from here on nothing throws.
            _settings = settings;
            _stepIndex = stepIndex;
            Time = time;
            DivergenceCount = divergences;
            LastDivergence = lastDivergence;
            _ccdShapeCount = ccdShapes;
            Bodies = bodies;
            Shapes = shapes;
            Joints = joints;
            _broadPhase = broadPhase;
            IgnoredPairs = ignored;
            IgnoredPairList = new System.Collections.Generic.List<ulong>(ignoredList);
            _narrowPhase.Restore(graph, source, manifoldCount);
            _shapeMotion = shapeMotion;
            _shapeRadius = shapeRadius;
            _shapePose = shapePose;
            _shapePoseStep = shapePoseStep;
            _fatBoxStep = fatBoxStep;
            if (_refit.Length < _shapeMotion.Length)
            {
                _refit = new bool[_shapeMotion.Length];
                _wantedBox = new Aabb[_shapeMotion.Length];
            }
            _islands = new IslandBuilder();
            _islands.RestoreSleepRings(sleepNext);
            for (int i = 0; i < removalCount; i++) removals[i] = removals[i].InWorld(Id);
            _removalEvents = removals;
            _removalEventCount = removalCount;
            _eventCount = 0;
            _jointBreakCount = 0;
            _queryBoundsStale = true;
            _profile = default;
            ResetStatistics();
            commitStage?.Invoke();
        }

        // The links between the storages: every live shape's body, every live body's shape list,
        // every live contact's shapes and bodies, in range and live.
        static void CheckLinks(StateReader r, BodyStorage bodies, ShapeStorage shapes, ContactGraph graph)
        {
            for (int k = 0; k < shapes.ActiveCount; k++)
            {
                int s = shapes.Active[k];
                int b = shapes.Body[s];
                if ((uint)b >= (uint)bodies.SlotCount || bodies.ActiveIndex[b] < 0) throw r.Error($"shape {s} belongs to body slot {b}, which is not live.");
                if (shapes.NextInBody[s] < -1 || shapes.NextInBody[s] >= shapes.SlotCount) throw r.Error($"shape {s} links to shape {shapes.NextInBody[s]}.");
            }
            for (int k = 0; k < bodies.ActiveCount; k++)
            {
                int b = bodies.Active[k];
                int s = bodies.FirstShape[b];
                if (s < -1 || s >= shapes.SlotCount) throw r.Error($"body {b} starts its shape list at {s}.");
            }
            for (int k = 0; k < graph.DenseCount; k++)
            {
                ref Contact c = ref graph.Contacts[graph.Dense[k]];
                if ((uint)c.ShapeA >= (uint)shapes.SlotCount || (uint)c.ShapeB >= (uint)shapes.SlotCount
                    || (uint)c.BodyA >= (uint)bodies.SlotCount || (uint)c.BodyB >= (uint)bodies.SlotCount)
                    throw r.Error($"contact {graph.Dense[k]} names shapes or bodies outside the state.");
            }
        }
    }
}
