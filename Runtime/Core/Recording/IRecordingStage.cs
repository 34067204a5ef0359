namespace Fulcrum
{
    /// <summary>
    /// A stage from another assembly (the soft bodies) that a <see cref="Recorder"/> asks for
    /// its part of a recording, the way <see cref="IStateStage"/> joins a saved state: Core
    /// writes the rigid data and leaves the soft-body blocks of the layout to this hook.
    /// </summary>
    internal interface IRecordingStage
    {
        /// <summary>The stage's block writer for one recording: what exists now is what it records.</summary>
        IRecordingBlock BeginRecording(World world);
    }

    /// <summary>One recording's view of a stage (Documentation~/RecordingFormat.md, the soft-body parts).</summary>
    internal interface IRecordingBlock
    {
        /// <summary>Writes the stage's header table (for the soft bodies: the count, then each mesh).</summary>
        void WriteHeader(RecordingWriter writer);

        /// <summary>The stage's energy now, J (the frame's soft-body energy field).</summary>
        float Energy();

        /// <summary>Writes the stage's per-frame block; allocates nothing once warm.</summary>
        void WriteFrame(RecordingWriter writer);
    }
}
