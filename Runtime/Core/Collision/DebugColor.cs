namespace Fulcrum.Collision
{
    /// <summary>The colours the world's debug drawing uses (0xAARRGGBB).</summary>
    public static class DebugColor
    {
        /// <summary>Shape outlines of awake bodies.</summary>
        public const uint Awake = 0xFFE0E0E0;
        /// <summary>Shape outlines of sleeping bodies.</summary>
        public const uint Asleep = 0xFF6080A0;
        /// <summary>Shape outlines of static bodies.</summary>
        public const uint Static = 0xFF60C060;
        /// <summary>Tight shape bounds.</summary>
        public const uint Bounds = 0xFFFF00FF;
        /// <summary>Fat bounds of tree leaves.</summary>
        public const uint TreeLeaf = 0xFF00C0C0;
        /// <summary>Internal tree nodes.</summary>
        public const uint TreeNode = 0x80808080;
        /// <summary>Contact points that penetrate.</summary>
        public const uint Penetrating = 0xFFFF3030;
        /// <summary>Speculative contact points (positive separation).</summary>
        public const uint Speculative = 0xFFFFD020;
        /// <summary>Contact normals.</summary>
        public const uint Normal = 0xFF40A0FF;
    }
}
