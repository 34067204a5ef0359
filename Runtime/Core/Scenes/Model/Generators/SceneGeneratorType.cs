namespace Fulcrum.Scenes
{
    /// <summary>The <c>type</c> of a generator (JSON: <c>tower</c>, <c>pyramid</c>, <c>wall</c>, <c>pile</c>, <c>chain</c>, <c>dominoes</c>).</summary>
    public enum SceneGeneratorType : byte
    {
        /// <summary>A vertical stack of boxes: <see cref="SceneTower"/>.</summary>
        Tower = 0,
        /// <summary>A two-dimensional pyramid of boxes: <see cref="ScenePyramid"/>.</summary>
        Pyramid = 1,
        /// <summary>A wall of bricks, rows staggered: <see cref="SceneWall"/>.</summary>
        Wall = 2,
        /// <summary>A grid pile of boxes, spheres or capsules: <see cref="ScenePile"/>.</summary>
        Pile = 3,
        /// <summary>Box links joined by ball joints: <see cref="SceneChain"/>.</summary>
        Chain = 4,
        /// <summary>A row of standing dominoes: <see cref="SceneDominoes"/>.</summary>
        Dominoes = 5,
    }
}
