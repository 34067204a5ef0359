using System.Runtime.CompilerServices;

// Tests inject contact events and read internal state of the host and the bridge.
[assembly: InternalsVisibleTo("Fulcrum.Tests")]
[assembly: InternalsVisibleTo("Fulcrum.Unity")]
