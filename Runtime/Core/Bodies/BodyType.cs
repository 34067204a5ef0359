namespace Fulcrum
{
    /// <summary>How a body moves.</summary>
    public enum BodyType : byte
    {
        /// <summary>Never moves; infinite mass. Cheapest: no integration, no sleeping logic.</summary>
        Static = 0,
        /// <summary>Moved by the user (velocity or a target pose); infinite mass, pushes dynamic bodies.</summary>
        Kinematic = 1,
        /// <summary>Moved by forces, contacts and joints.</summary>
        Dynamic = 2,
    }
}
