using System;
using System.Reflection;
using System.Runtime.InteropServices;
using System.Text;
using Fulcrum.Collision;
using Fulcrum.Dynamics;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    /// <summary>
    /// A fingerprint of the memory layout of every struct a world state stores as a memory image
    /// (size, then each field's name and type, nested structs included). Written in the header
    /// and compared on restore, so that a state from a build whose structs differ is refused with
    /// a clear message instead of being read into the wrong fields. Computed once by reflection.
    /// </summary>
    internal static class StateLayout
    {
        static ulong s_hash;

        /// <summary>The types whose memory images a state holds; other assemblies add theirs through <see cref="IStateStage.LayoutTypes"/>.</summary>
        static readonly Type[] CoreTypes =
        {
            typeof(WorldSettings), typeof(System.Numerics.Vector3), typeof(System.Numerics.Quaternion), typeof(Mat3), typeof(Aabb), typeof(Pose),
            typeof(BodyType), typeof(CombineMode), typeof(TreeNode), typeof(Contact), typeof(ContactManifold), typeof(JointData), typeof(ContactEvent),
            typeof(DivergenceKind), typeof(ShapeType),
        };

        /// <summary>The fingerprint of the core layouts combined with <paramref name="extra"/> types.</summary>
        public static ulong Hash(Type[]? extra)
        {
            if (extra == null || extra.Length == 0)
            {
                if (s_hash == 0) s_hash = Compute(CoreTypes, null);
                return s_hash;
            }
            return Compute(CoreTypes, extra);
        }

        static ulong Compute(Type[] types, Type[]? extra)
        {
            var text = new StringBuilder();
            foreach (Type t in types) Describe(t, text);
            if (extra != null) foreach (Type t in extra) Describe(t, text);
            return Fnv1a(Encoding.UTF8.GetBytes(text.ToString()));
        }

        static void Describe(Type t, StringBuilder text)
        {
            text.Append(t.FullName).Append(':').Append(SizeOf(t)).Append('{');
            if (t.IsEnum) text.Append(Enum.GetUnderlyingType(t).Name);
            else if (!t.IsPrimitive)
            {
                foreach (FieldInfo f in t.GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic))
                {
                    text.Append(f.Name).Append(' ');
                    if (f.FieldType.IsValueType && !f.FieldType.IsPrimitive && !f.FieldType.IsEnum) Describe(f.FieldType, text);
                    else text.Append(f.FieldType.FullName);
                    text.Append(';');
                }
            }
            text.Append('}');
        }

        // The managed size (what MemoryMarshal.AsBytes sees), not the marshalled one.
        static int SizeOf(Type t)
        {
            MethodInfo m = typeof(StateLayout).GetMethod(nameof(ManagedSize), BindingFlags.Static | BindingFlags.NonPublic)!;
            return (int)m.MakeGenericMethod(t).Invoke(null, null)!;
        }

        static int ManagedSize<T>() where T : struct => MemoryMarshal.AsBytes(new Span<T>(new T[1])).Length;

        /// <summary>64-bit FNV-1a of a byte span (the header's checksum and the layout fingerprint).</summary>
        public static ulong Fnv1a(ReadOnlySpan<byte> bytes)
        {
            ulong h = 14695981039346656037UL;
            for (int i = 0; i < bytes.Length; i++)
            {
                h ^= bytes[i];
                h *= 1099511628211UL;
            }
            return h;
        }
    }
}
