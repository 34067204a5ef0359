namespace Fulcrum.Collision
{
    /// <summary>What <see cref="NearestHits"/> orders a query's hits by (ray casts, shape casts).</summary>
    internal interface IQueryHit
    {
        /// <summary>Distance along the query, metres.</summary>
        float Distance { get; }

        /// <summary>The shape hit.</summary>
        ShapeHandle Shape { get; }
    }
}
