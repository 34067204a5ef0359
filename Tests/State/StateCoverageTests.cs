using System;
using System.Collections;
using System.Collections.Generic;
using System.Reflection;
using Fulcrum.Scenes;
using Fulcrum.SoftBodies;
using Fulcrum.Tests.RigidScenes;
using NUnit.Framework;

namespace Fulcrum.Tests.State
{
    /// <summary>
    /// Guards World.SaveState against a field added later and forgotten: after a restore, every
    /// field reachable from the world (bodies, shapes, joints, contacts, broad phase, islands,
    /// soft bodies) equals the original's, except the fields listed here as scratch (rebuilt or
    /// overwritten before a step reads them) or as outputs of the last step. A new field fails
    /// this test until it is saved or listed with its reason.
    /// </summary>
    public partial class StateCoverageTests
    {
        // Declaring type name + "." + field name (auto-property backing fields by property name).
        static readonly HashSet<string> NotState = new HashSet<string>
        {
            // Identity and the step's own bookkeeping.
            "World.<Id>k__BackingField", "World._inStep", "World._profile", "World.Diverged",
            // Outputs of the last step (documented: empty after a restore until the next step).
            "World._events", "World._eventCount", "World._jointBreaks", "World._jointBreakCount",
            "World.StatMaxPenetration", "World.StatContactCount", "World.StatMaxJointError", "World.StatReusedManifoldPairs",
            "NarrowPhase.Touching", "NarrowPhase.MaxPenetration", "NarrowPhase.ReusedPairs", "NarrowPhase.ParallelSteps", "NarrowPhase.ParallelRewrites",
            // Scratch of one step, cleared or overwritten before it is read.
            "NarrowPhase._sortKeys", "NarrowPhase._sortItems", "NarrowPhase._sortCount", "NarrowPhase._contactOrder", "World._eventOrder",
            "World._stepEvents", "World._stepEventKeys", "World._stepEventOrder", "World._stepEventCount",
            "NarrowPhase._in", "NarrowPhase._anyWoken", "NarrowPhase._contactBuffer", "NarrowPhase._pointCache",
            "NarrowPhase._job", "NarrowPhase._slot", "World._freeBodies", "NarrowPhase._reuseCosHalfAngle",
            "World._workers", "World._scheduler", "World._solverContext", "World._pgs", "World._tgs",
            "World._stepConstrained", "World._solvedInStep", "World._refit", "World._wantedBox", "World._boundsJob", "World._pairSearch",
            // Queries: their own scratch, and bounds refreshed lazily before the next query.
            "World._queryBuffer", "World._rayHits", "World._castHits", "World._overlaps", "World._queryBoundsStale",
            // Island building: only the sleeping rings (SleepNext) live across steps.
            "IslandBuilder._parent", "IslandBuilder._islandRest", "IslandBuilder._ringHead", "IslandBuilder._ringTail",
            "IslandBuilder.Manifolds", "IslandBuilder.ManifoldCount", "IslandBuilder.Joints", "IslandBuilder.JointCount",
            "IslandBuilder.AwakeBodies", "IslandBuilder.AwakeCount",
            // The free list's spare capacity (its entries are compared through the count).
            "SlotAllocator._free",
            // Soft bodies: the per-step contact and pair searches (the contacts' held flags for the
            // Newton solver are saved by SoftBody.WriteState and checked by the round-trip tests), job objects and scratch.
            "SoftBodySystem._coupling", "SoftBodySystem._softContacts", "SoftBodySystem.Diverged",
            "SoftBody._tetJob", "SoftBody._membraneJob", "SoftBody._bendingJob", "SoftBody.Contacts", "SoftBody.SelfContacts", "SoftBody._scratch",
            // The step's soft-soft pairs and the count of substeps begun: set at the start of every step.
            "SoftBody.SoftPairs", "SoftBody.SubstepsBegun",
            // The tet kernels' (W, FreeW, M, inverted mark) per vertex, the same masses per element, and
            // whether the body is loaded from outside (the volume floor): set from the saved arrays at
            // the start of every step.
            "TetStream.Masses", "TetStream.ElementMasses", "TetStream.Loaded", "SoftBody._startLargestJ", "SoftBody._cleanEnd",
            // The step-start velocities and what the blow-up check measured at the end of the
            // substeps (for a step taken again): copied and measured anew in every step before use.
            "SoftBody.VStart", "SoftBody._endLargestJ", "SoftBody._endInverted", "SoftBody._endBlown", "SoftBody._endMeasured",
            // An XPBD substep's predicted positions and the rounding its prediction carries to the
            // next substep: set in every substep, the carry cleared at the start of every step.
            "SoftBody.XPredicted", "SoftBody.XResidual",
            // Timing of past passes (pool or calling thread); the choice never changes results.
            "SoftBody._threadChoice",
        };

        // Pools whose entries past a count are spare (stale from earlier use, never read): the
        // field and the field of the same object that holds the count (or a multiple of it).
        static readonly Dictionary<string, (string Count, int PerItem)> Pools = new Dictionary<string, (string, int)>
        {
            ["BroadPhase._moved"] = ("_movedCount", 1),
            ["ContactSet.Source"] = ("ManifoldCount", 1),
            ["ContactGraph.Dense"] = ("DenseCount", 1),
            ["World._removalEvents"] = ("_removalEventCount", 1),
        };

        static void Compare(object? a, object? b, string path, List<string> diffs, HashSet<object> seen, int limit = -1)
        {
            if (diffs.Count > 200) return;
            if (a == null || b == null)
            {
                if (a != null || b != null) diffs.Add(path + " (null on one side)");
                return;
            }
            Type t = a.GetType();
            if (t != b.GetType()) { diffs.Add(path + " (type)"); return; }
            if (t.IsPrimitive || t.IsEnum || t == typeof(string) || t.IsPointer) { if (!a.Equals(b)) diffs.Add(path); return; }
            if (a is Delegate || a is MemberInfo) return;
            if (t.IsValueType && !HasReferences(t)) { if (!a.Equals(b)) diffs.Add(path); return; }
            if (!t.IsValueType && !seen.Add(a)) return;
            if (a is Array arrayA)
            {
                var arrayB = (Array)b;
                if (arrayA.Length != arrayB.Length) { diffs.Add($"{path}.Length {arrayA.Length} != {arrayB.Length}"); return; }
                int n = limit >= 0 ? limit : arrayA.Length;
                for (int i = 0; i < n && diffs.Count <= 200; i++) Compare(arrayA.GetValue(i), arrayB.GetValue(i), $"{path}[{i}]", diffs, seen);
                return;
            }
            if (a is IEnumerable sequenceA && t.Namespace != null && t.Namespace.StartsWith("System"))
            {
                var listA = new List<object?>();
                var listB = new List<object?>();
                foreach (object? o in sequenceA) listA.Add(o);
                foreach (object? o in (IEnumerable)b) listB.Add(o);
                if (listA.Count != listB.Count) { diffs.Add($"{path}.Count {listA.Count} != {listB.Count}"); return; }
                for (int i = 0; i < listA.Count; i++) Compare(listA[i], listB[i], $"{path}[{i}]", diffs, seen);
                return;
            }
            for (Type? d = t; d != null && d != typeof(object) && d != typeof(ValueType); d = d.BaseType)
            {
                foreach (FieldInfo f in d.GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.DeclaredOnly))
                {
                    string key = d.Name + "." + f.Name;
                    if (NotState.Contains(key)) continue;
                    int count = -1;
                    if (Pools.TryGetValue(key, out var pool))
                        count = pool.PerItem * (int)d.GetField(pool.Count, BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic)!.GetValue(a)!;
                    Compare(f.GetValue(a), f.GetValue(b), path + "." + f.Name, diffs, seen, count);
                }
            }
        }

        static bool HasReferences(Type t)
        {
            foreach (FieldInfo f in t.GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic))
            {
                Type ft = f.FieldType;
                if (!ft.IsValueType) return true;
                if (!ft.IsPrimitive && !ft.IsEnum && HasReferences(ft)) return true;
            }
            return false;
        }

        static SceneInstance Scene(string name)
        {
            SceneInstance scene = RigidSceneFiles.Build(name);
            if (scene.Document.SoftBodies.Count > 0) SceneSoftBodyBuilder.Build(scene, directory: RigidSceneFiles.ScenesDirectory);
            return scene;
        }

        [TestCase("pyramid", 150)]
        [TestCase("ragdolls", 60)]
        [TestCase("jelly-on-mesh-ramp", 40)]
        [TestCase("pinned-flag", 30)]
        public void Every_field_a_step_reads_is_restored(string name, int steps)
        {
            SceneInstance a = Scene(name);
            RigidSceneFiles.Run(a, steps);
            byte[] state = StateRoundTripTests.Save(a.World);
            SceneInstance b = Scene(name);
            StateRoundTripTests.Restore(b.World, state);

            var diffs = new List<string>();
            Compare(a.World, b.World, "World", diffs, new HashSet<object>(ReferenceComparer.Instance));
            var fields = new SortedSet<string>();
            foreach (string d in diffs) fields.Add(System.Text.RegularExpressions.Regex.Replace(d, @"\[\d+\]", "[]"));
            Assert.That(fields, Is.Empty, "fields that differ after a restore: save them, or list them in NotState with the reason");
        }
    }
}
