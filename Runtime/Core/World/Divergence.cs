namespace Fulcrum
{
    /// <summary>What made a body diverge (see <see cref="World.Diverged"/>).</summary>
    public enum DivergenceKind : byte
    {
        /// <summary>A position, rotation or velocity became NaN or infinite in the step.</summary>
        NonFinite = 0,
        /// <summary>The body left the world bounds (|x|, |y| or |z| above <see cref="Limits.MaxPosition"/>).</summary>
        OutOfBounds = 1,
    }

    /// <summary>
    /// A body a step could not keep finite or inside the world: the world put it back at its
    /// pose from the start of that step, stopped it, and reported it here.
    /// </summary>
    public readonly struct Divergence
    {
        /// <summary>The body.</summary>
        public readonly BodyHandle Body;
        /// <summary>The step it diverged in (<see cref="World.StepIndex"/> before that step ended).</summary>
        public readonly long Step;
        /// <summary>What happened.</summary>
        public readonly DivergenceKind Kind;

        /// <summary>A divergence of <paramref name="body"/> in step <paramref name="step"/>.</summary>
        public Divergence(BodyHandle body, long step, DivergenceKind kind)
        {
            Body = body;
            Step = step;
            Kind = kind;
        }

        /// <inheritdoc/>
        public override string ToString() => Kind == DivergenceKind.NonFinite
            ? $"body {Body} became non-finite in step {Step}"
            : $"body {Body} left the world bounds (+-{Limits.MaxPosition:G} m) in step {Step}";
    }
}
