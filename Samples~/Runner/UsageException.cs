using System;

namespace Fulcrum.Runner;

/// <summary>A bad command line or scene: the message is the one-line reason, naming the flag or field.</summary>
public sealed class UsageException(string message, int exitCode = Cli.ExitUsage) : Exception(message)
{
    /// <summary>The process exit code to return.</summary>
    public int ExitCode { get; } = exitCode;
}
