namespace Fulcrum.Collision
{
    /// <summary>
    /// Which shapes a world query (ray cast, shape cast, overlap) may report. Start from
    /// <see cref="Default"/>.
    /// </summary>
    public struct QueryFilter
    {
        /// <summary>Bit mask of the layers to report: a shape is seen when bit (1 &lt;&lt; its layer) is set. Default: all.</summary>
        public uint LayerMask;
        /// <summary>Whether sensor shapes are reported. Default: false.</summary>
        public bool IncludeSensors;
        /// <summary>A body whose shapes are ignored (the caster itself, say). Default: none.</summary>
        public BodyHandle IgnoreBody;

        /// <summary>All layers, no sensors, nothing ignored.</summary>
        public static QueryFilter Default => new QueryFilter { LayerMask = uint.MaxValue };

        /// <summary>The default filter restricted to the layers in <paramref name="layerMask"/>.</summary>
        public static QueryFilter Layers(uint layerMask) => new QueryFilter { LayerMask = layerMask };
    }
}
