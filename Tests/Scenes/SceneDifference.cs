using System;
using System.Collections;
using System.Numerics;
using System.Reflection;
using Fulcrum.Mathematics;

namespace Fulcrum.Tests.Scenes
{
    /// <summary>
    /// Structural comparison of scene model objects by reflection over their public
    /// properties: floats compare bit for bit (so 0.1f vs 0.100000001f or 0 vs -0 differ).
    /// Returns the path of the first difference, or null when equal.
    /// </summary>
    static class SceneDifference
    {
        public static string? Find(object? a, object? b, string path = "$")
        {
            if (a == null || b == null) return a == null && b == null ? null : $"{path}: {a ?? "null"} vs {b ?? "null"}";
            if (a.GetType() != b.GetType()) return $"{path}: type {a.GetType().Name} vs {b.GetType().Name}";
            switch (a)
            {
                case float fa: return Bits(fa) == Bits((float)b) ? null : $"{path}: {fa:R} vs {(float)b:R}";
                case Vector3 va: return Find(va.X, ((Vector3)b).X, path + ".x") ?? Find(va.Y, ((Vector3)b).Y, path + ".y") ?? Find(va.Z, ((Vector3)b).Z, path + ".z");
                case Vector2 wa: return Find(wa.X, ((Vector2)b).X, path + ".x") ?? Find(wa.Y, ((Vector2)b).Y, path + ".y");
                case Quaternion qa:
                {
                    var qb = (Quaternion)b;
                    return Find(qa.X, qb.X, path + ".x") ?? Find(qa.Y, qb.Y, path + ".y") ?? Find(qa.Z, qb.Z, path + ".z") ?? Find(qa.W, qb.W, path + ".w");
                }
                case Mat3 ma:
                {
                    var mb = (Mat3)b;
                    return Find(ma.C0, mb.C0, path + ".c0") ?? Find(ma.C1, mb.C1, path + ".c1") ?? Find(ma.C2, mb.C2, path + ".c2");
                }
                case string or int or bool or Enum: return a.Equals(b) ? null : $"{path}: {a} vs {b}";
                case IList la:
                {
                    var lb = (IList)b;
                    if (la.Count != lb.Count) return $"{path}: {la.Count} items vs {lb.Count}";
                    for (int i = 0; i < la.Count; i++)
                        if (Find(la[i], lb[i], $"{path}[{i}]") is string d) return d;
                    return null;
                }
            }
            foreach (PropertyInfo p in a.GetType().GetProperties(BindingFlags.Public | BindingFlags.Instance))
            {
                if (p.GetIndexParameters().Length > 0) continue;
                if (Find(p.GetValue(a), p.GetValue(b), path + "." + p.Name) is string d) return d;
            }
            return null;
        }

        static int Bits(float f) => BitConverter.SingleToInt32Bits(f);
    }
}
