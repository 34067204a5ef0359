using System.Collections.Generic;
using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "dominoes", "count": n, "size": [0.1, 1, 0.5], "axis": "x", "spacing": 0.4, "tipSpeed": 0, "at": [0, 0, 0]}</c>:
    /// <c>count</c> upright dominoes in a row along <c>axis</c>, standing on y = at.y, the first
    /// one's bottom centred on <c>at</c>. <c>size</c> is [along (thickness), up (height),
    /// across (width)]; <c>spacing</c> is the gap between neighbouring faces. <c>tipSpeed</c>
    /// (rad/s, default 0) starts the first domino turning about its leading bottom edge,
    /// toward +axis, which knocks the row over. Body 0 is the first domino.
    /// </summary>
    public sealed class SceneDominoes : SceneGenerator
    {
        /// <summary>Dominoes 0.1 x 1 x 0.5 with 0.4 m gaps along x, not tipped.</summary>
        public SceneDominoes() : base(new Vector3(0.1f, 1f, 0.5f), 0.4f) { }

        /// <inheritdoc/>
        public override SceneGeneratorType Type => SceneGeneratorType.Dominoes;

        /// <summary><c>count</c>: number of dominoes, &gt;= 1. Required.</summary>
        public int Count { get; set; }

        /// <summary><c>axis</c>: the direction of the row. Default: x.</summary>
        public SceneAxis Axis { get; set; }

        /// <summary><c>tipSpeed</c>: initial angular speed of the first domino about its leading bottom edge, rad/s. Default: 0.</summary>
        public float TipSpeed { get; set; }

        /// <inheritdoc/>
        public override long BodyCount => Count;

        /// <inheritdoc/>
        public override void Expand(List<SceneBody> bodies, List<SceneJoint> joints)
        {
            Vector3 along = SceneAxisFrame.Along(Axis);
            Vector3 worldSize = SceneAxisFrame.ToWorld(Axis, Size);
            float pitch = Size.X + Spacing;
            var up = new Vector3(0, 0.5f * Size.Y, 0);
            for (int i = 0; i < Count; i++)
            {
                SceneBody body = NewBody(i, At + up + along * (i * pitch), BoxOf(worldSize));
                if (i == 0 && TipSpeed != 0)
                {
                    // Rotation about the leading bottom edge: w = s (up x along) turns the top
                    // toward +along; the centre moves with v = w x (c - pivot).
                    Vector3 w = TipSpeed * Vector3.Cross(Vector3.UnitY, along);
                    Vector3 fromPivot = up - along * (0.5f * Size.X);
                    body.AngularVelocity = w;
                    body.Velocity = Vector3.Cross(w, fromPivot);
                }
                bodies.Add(body);
            }
        }
    }
}
