using System.Collections.Generic;

namespace Fulcrum.Runner;

/// <summary>The settings no other setting beats on both cost and error.</summary>
static class ParetoFront
{
    /// <summary>
    /// Indices of the points not dominated by any other: none is at least as cheap and at
    /// least as accurate while strictly better in one of the two. Sorted by cost.
    /// </summary>
    public static List<int> Of(IReadOnlyList<(double cost, double error)> points)
    {
        var front = new List<int>();
        for (int i = 0; i < points.Count; i++)
        {
            bool dominated = false;
            for (int j = 0; j < points.Count && !dominated; j++)
            {
                if (j == i) continue;
                (double c, double e) = points[j];
                dominated = c <= points[i].cost && e <= points[i].error && (c < points[i].cost || e < points[i].error);
            }
            if (!dominated) front.Add(i);
        }
        front.Sort((a, b) => points[a].cost.CompareTo(points[b].cost));
        return front;
    }
}
