using System.Collections.Generic;
using System.Linq;
using System.Text.RegularExpressions;
using Fulcrum.Runner;
using NUnit.Framework;

namespace Fulcrum.Tests.Scenes
{
    public class SweepPlotTests
    {
        [Test]
        public void Pareto_front_keeps_exactly_the_undominated_points_in_order_of_cost()
        {
            var points = new List<(double, double)>
            {
                (1.0, 0.5),   // 0: cheapest
                (2.0, 0.6),   // 1: dominated by 0
                (2.0, 0.1),   // 2: front
                (3.0, 0.1),   // 3: dominated by 2 (same error, dearer)
                (5.0, 0.01),  // 4: front
                (0.5, 0.9),   // 5: front (cheapest of all)
                (5.0, 0.01),  // 6: a tie with 4: neither dominates
            };
            Assert.That(ParetoFront.Of(points), Is.EqualTo(new[] { 5, 0, 2, 4, 6 }));
        }

        [Test]
        public void Plot_draws_one_line_per_solver_and_rings_the_front()
        {
            var points = new List<SweepPoint>
            {
                new(SolverType.Pgs, 1, 1, 0.016f, 0.10, 0, null, 0.30f, 0, null),
                new(SolverType.Pgs, 4, 1, 0.016f, 0.20, 0, null, 0.10f, 0, null),
                new(SolverType.Tgs, 1, 4, 0.016f, 0.15, 0, null, 0.05f, 0, null),
                new(SolverType.Tgs, 4, 4, 0.016f, 0.40, 0, null, 0.00f, 0, null),
            };
            string svg = SweepPlot.Svg("t", "reference error (m)", points, p => p.ReferenceError ?? 0);
            Assert.That(Regex.Matches(svg, "<polyline").Count, Is.EqualTo(3), "PGS, TGS and the front");
            Assert.That(Regex.Matches(svg, "r=\"7\"").Count, Is.EqualTo(3), "front: pgs 1, tgs 1x4, tgs 4x4");
            Assert.That(Regex.Matches(svg, "<circle").Count, Is.EqualTo(4 + 3 + 1), "points, front rings, legend ring");
            TestContext.WriteLine(svg);
        }
    }
}
