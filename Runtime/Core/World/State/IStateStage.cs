using System;

namespace Fulcrum
{
    /// <summary>
    /// A stage from another assembly (the soft bodies) whose state <see cref="World.SaveState"/>
    /// writes and <see cref="World.RestoreState"/> reads, as one section of the same file.
    /// </summary>
    internal interface IStateStage
    {
        /// <summary>True when the stage has objects whose state must be saved.</summary>
        bool HasState { get; }

        /// <summary>Structs the stage writes as memory images (fingerprinted in the header).</summary>
        Type[] LayoutTypes { get; }

        /// <summary>Writes the stage's state.</summary>
        void SaveState(StateWriter writer);

        /// <summary>
        /// Reads the stage's state and checks it against the stage, changing nothing; returns
        /// what applies it, which the world calls only once every section has been read.
        /// </summary>
        Action PrepareRestore(StateReader reader);
    }
}
