using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// What the contacts carry from step to step (holds, sticks, rests, the normals met): kept at a
    /// step's start so that a step can be taken again, written to and read from the world state.
    /// </summary>
    internal sealed partial class ShapeContactSolver
    {
        // What the last step left for this one (the arrays WriteState writes), kept at the step's
        // start so that a step taken again (SoftBodySystem) starts from it.
        bool[] _keptHold = Array.Empty<bool>(), _keptStuck = Array.Empty<bool>(), _keptRest = Array.Empty<bool>(), _keptFeatureMet = Array.Empty<bool>();
        Vector3[] _keptNormal = Array.Empty<Vector3>(), _keptRestNormal = Array.Empty<Vector3>(), _keptRestVelocity = Array.Empty<Vector3>();

        /// <summary>Keeps what the last step left for this one (see <see cref="BackToStepStart"/>).</summary>
        internal void KeepStepStart()
        {
            Keep(_holdNow, ref _keptHold);
            Keep(_stuckNow, ref _keptStuck);
            Keep(_restNow, ref _keptRest);
            Keep(_featureMetNow, ref _keptFeatureMet);
            Keep(_normal, ref _keptNormal);
            Keep(_restNormalNow, ref _keptRestNormal);
            Keep(_restVelocityNow, ref _keptRestVelocity);
        }

        /// <summary>
        /// Puts back what <see cref="KeepStepStart"/> kept, as a restored state does (the last
        /// substep's flags cleared): the step is taken again from its start.
        /// </summary>
        internal void BackToStepStart()
        {
            Back(_keptHold, _holdNow, _holdLast);
            Back(_keptStuck, _stuckNow, _stuckLast);
            Back(_keptRest, _restNow, _restLast);
            Back(_keptFeatureMet, _featureMetNow, _featureMetLast);
            Back(_keptNormal, _normal, null);
            Back(_keptRestNormal, _restNormalNow, _restNormalLast);
            Back(_keptRestVelocity, _restVelocityNow, _restVelocityLast);
        }

        static void Keep<T>(T[] now, ref T[] kept)
        {
            if (kept.Length != now.Length) kept = new T[now.Length];
            Array.Copy(now, kept, now.Length);
        }

        // A step that grew the arrays found them empty: they go back to all clear.
        static void Back<T>(T[] kept, T[] now, T[]? last)
        {
            if (kept.Length == now.Length) Array.Copy(kept, now, now.Length);
            else Array.Clear(now, 0, now.Length);
            if (last != null) Array.Clear(last, 0, last.Length);
        }

        /// <summary>Writes what the next step reads: which vertices an immovable shape held in the last substep, and the normals, which static friction held, which vertices' surface triangles a shape's feature met, and which vertices rest on a shape (with its normal and surface velocity there).</summary>
        internal void WriteState(StateWriter w)
        {
            w.WriteArray(_holdNow);
            w.WriteArray(_normal);
            w.WriteArray(_stuckNow);
            w.WriteArray(_featureMetNow);
            w.WriteArray(_restNow);
            w.WriteArray(_restNormalNow);
            w.WriteArray(_restVelocityNow);
        }

        /// <summary>Reads what <see cref="WriteState"/> wrote; the returned action applies it.</summary>
        internal Action PrepareRestore(StateReader r, int vertexCount)
        {
            bool[] held = r.ReadArray<bool>("soft contact holds");
            Vector3[] normal = r.ReadArrayExactly<Vector3>("soft contact normals", held.Length);
            bool[] stuck = r.ReadArrayExactly<bool>("soft contact static friction", held.Length);
            bool[] met = r.ReadArray<bool>("soft contact features met");
            if (met.Length != 0 && met.Length != vertexCount) throw r.Error($"soft contact features met for {met.Length} of {vertexCount} vertices.");
            if (held.Length != 0 && held.Length < vertexCount) throw r.Error($"soft contact holds for {held.Length} of {vertexCount} vertices.");
            bool[] rest = r.ReadArrayExactly<bool>("soft contact rests", held.Length);
            Vector3[] restNormal = r.ReadArrayExactly<Vector3>("soft contact rest normals", held.Length);
            Vector3[] restVelocity = r.ReadArrayExactly<Vector3>("soft contact rest surface velocities", held.Length);
            return () =>
            {
                _restNow = rest;
                _restLast = new bool[held.Length];
                _restNormalNow = restNormal;
                _restNormalLast = new Vector3[held.Length];
                _restVelocityNow = restVelocity;
                _restVelocityLast = new Vector3[held.Length];
                _holdNow = held;
                _holdLast = new bool[held.Length];
                _normal = normal;
                _stuckNow = stuck;
                _stuckLast = new bool[held.Length];
                _featureMetNow = met;
                _featureMetLast = new bool[met.Length];
                if (_pushed.Length != held.Length) AllocateSubstepScratch(held.Length);
            };
        }
    }
}
