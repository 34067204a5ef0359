using System.Collections.Generic;
using System.Globalization;
using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// An entry of <c>generators</c>: a recipe that expands to plain bodies (and joints, for a
    /// chain) named <c>&lt;name or type&gt;/&lt;i&gt;</c>, i from 0, bottom or first first. Every
    /// generator puts its bodies on the plane y = <c>at.y</c> (the lowest ones touch it) with no
    /// two bodies overlapping. Fields shared by all generators:
    /// <list type="bullet">
    /// <item><c>type</c> (required), <c>name</c> (optional; the prefix of the body names, default the type),</item>
    /// <item><c>at</c>: where the generator stands on the ground, m (each type says which point). Default [0, 0, 0],</item>
    /// <item><c>size</c>: full size of one body, m (default per type),</item>
    /// <item><c>spacing</c>: gap between neighbouring bodies, m, &gt;= 0 (default per type),</item>
    /// <item><c>mass</c>: kg per body (or <c>material</c> with a density; not both),</item>
    /// <item><c>material</c>: a material name for every body.</item>
    /// </list>
    /// </summary>
    public abstract class SceneGenerator
    {
        /// <summary>Creates a generator with its type's default size and spacing.</summary>
        protected SceneGenerator(Vector3 defaultSize, float defaultSpacing)
        {
            Size = defaultSize;
            Spacing = defaultSpacing;
        }

        /// <summary>The kind, written as the <c>type</c> field.</summary>
        public abstract SceneGeneratorType Type { get; }

        /// <summary><c>name</c>: the prefix of the generated names; null: the type's JSON name.</summary>
        public string? Name { get; set; }

        /// <summary><c>at</c>: the generator's base point on the ground, m. Default: 0.</summary>
        public Vector3 At { get; set; }

        /// <summary><c>size</c>: full size of one body, m, each &gt; 0.</summary>
        public Vector3 Size { get; set; }

        /// <summary><c>spacing</c>: gap between neighbouring bodies, m, &gt;= 0.</summary>
        public float Spacing { get; set; }

        /// <summary><c>mass</c>: kg per body, &gt; 0; null: from the material's density (or 1000 kg/m^3).</summary>
        public float? Mass { get; set; }

        /// <summary><c>material</c>: a material name for every body; null: the default material.</summary>
        public string? Material { get; set; }

        /// <summary>The prefix of every generated name: <see cref="Name"/>, or the type's JSON name.</summary>
        public string Prefix => Name ?? SceneNames.Of(Type);

        /// <summary>How many bodies <see cref="Expand"/> makes (for checks before expanding).</summary>
        public abstract long BodyCount { get; }

        /// <summary>Appends the generated bodies and joints to the lists.</summary>
        public abstract void Expand(List<SceneBody> bodies, List<SceneJoint> joints);

        /// <summary>The name of the generated item <paramref name="index"/>.</summary>
        protected string ItemName(int index) => Prefix + "/" + index.ToString(CultureInfo.InvariantCulture);

        /// <summary>A dynamic body named for <paramref name="index"/> with this generator's mass and material.</summary>
        protected SceneBody NewBody(int index, Vector3 position, SceneShape shape) => new SceneBody
        {
            Name = ItemName(index),
            Type = BodyType.Dynamic,
            Shape = shape,
            Mass = Mass,
            Material = Material,
            Position = position,
        };

        /// <summary>
        /// Row <paramref name="row"/> of a flat stack of boxes of <see cref="Size"/> ([along, up, across]) in the
        /// vertical plane along <paramref name="axis"/> (pyramid, wall): <paramref name="n"/> boxes <see cref="Spacing"/>
        /// apart, centred on <see cref="At"/>, on the rows below (row 0 rests on y = at.y), named from
        /// <paramref name="index"/> on in the +axis direction.
        /// </summary>
        private protected void AddRow(List<SceneBody> bodies, SceneAxis axis, int row, int n, ref int index)
        {
            Vector3 along = SceneAxisFrame.Along(axis);
            Vector3 worldSize = SceneAxisFrame.ToWorld(axis, Size);
            float pitch = Size.X + Spacing;
            float y = At.Y + 0.5f * Size.Y + row * Size.Y;
            for (int j = 0; j < n; j++)
            {
                Vector3 p = At + along * ((j - 0.5f * (n - 1)) * pitch);
                bodies.Add(NewBody(index++, new Vector3(p.X, y, p.Z), BoxOf(worldSize)));
            }
        }

        /// <summary>A box shape of full size <paramref name="worldSize"/>.</summary>
        protected static SceneBox BoxOf(Vector3 worldSize) => new SceneBox { HalfExtents = worldSize * 0.5f };
    }
}
