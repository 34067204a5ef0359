using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace Fulcrum.Runner;

/// <summary>
/// The sweep's plot as a hand-written SVG (no plotting package is available): error against
/// ms/step, one polyline per solver through its settings in order of cost, each point
/// labelled with its iterations x substeps, and the Pareto front (over all solvers) drawn
/// as a dashed staircase through ringed points. Both axes are logarithmic when the data
/// spans more than a factor of ten, else linear.
/// </summary>
static class SweepPlot
{
    const double Width = 760, Height = 500, Left = 80, Right = 170, Top = 40, Bottom = 60;

    static readonly Dictionary<SolverType, string> Colours = new() { [SolverType.Pgs] = "#d62728", [SolverType.Tgs] = "#1f77b4" };
    static readonly Dictionary<SolverType, string> NewtonColours = new() { [SolverType.Pgs] = "#9467bd", [SolverType.Tgs] = "#ff7f0e" };

    public static string Svg(string title, string errorName, IReadOnlyList<SweepPoint> points, Func<SweepPoint, double> error)
    {
        var xs = new double[points.Count];
        var ys = new double[points.Count];
        double floor = double.MaxValue;
        for (int i = 0; i < points.Count; i++)
        {
            xs[i] = Math.Max(points[i].MsPerStep, 1e-9);
            ys[i] = error(points[i]);
            if (ys[i] > 0) floor = Math.Min(floor, ys[i]);
        }
        // A zero error (the reference setting itself) sits one decade below the smallest non-zero one.
        floor = floor == double.MaxValue ? 1e-9 : floor / 10;
        bool clamped = false;
        for (int i = 0; i < ys.Length; i++)
        {
            clamped |= ys[i] < floor;
            ys[i] = Math.Max(ys[i], floor);
        }
        var x = new Axis(xs);
        var y = new Axis(ys);

        var svg = new StringBuilder();
        svg.Append(Inv($"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{Width}\" height=\"{Height}\" viewBox=\"0 0 {Width} {Height}\" font-family=\"sans-serif\" font-size=\"12\">\n"));
        svg.Append(Inv($"<rect width=\"{Width}\" height=\"{Height}\" fill=\"white\"/>\n"));
        svg.Append(Inv($"<text x=\"{Width / 2}\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">{Escape(title)}</text>\n"));
        double plotW = Width - Left - Right, plotH = Height - Top - Bottom;
        double Px(double v) => Left + x.Fraction(v) * plotW;
        double Py(double v) => Top + (1 - y.Fraction(v)) * plotH;

        svg.Append(Inv($"<rect x=\"{Left}\" y=\"{Top}\" width=\"{plotW}\" height=\"{plotH}\" fill=\"none\" stroke=\"#444\"/>\n"));
        foreach (double t in x.Ticks())
        {
            double px = Px(t);
            svg.Append(Inv($"<line x1=\"{px:F1}\" y1=\"{Top}\" x2=\"{px:F1}\" y2=\"{Top + plotH}\" stroke=\"#ddd\"/>\n"));
            svg.Append(Inv($"<text x=\"{px:F1}\" y=\"{Top + plotH + 16}\" text-anchor=\"middle\">{Label(t)}</text>\n"));
        }
        foreach (double t in y.Ticks())
        {
            double py = Py(t);
            svg.Append(Inv($"<line x1=\"{Left}\" y1=\"{py:F1}\" x2=\"{Left + plotW}\" y2=\"{py:F1}\" stroke=\"#ddd\"/>\n"));
            svg.Append(Inv($"<text x=\"{Left - 6}\" y=\"{py + 4:F1}\" text-anchor=\"end\">{Label(t)}</text>\n"));
        }
        svg.Append(Inv($"<text x=\"{Left + plotW / 2}\" y=\"{Height - 18}\" text-anchor=\"middle\">ms/step{(x.Log ? " (log)" : "")}</text>\n"));
        svg.Append(Inv($"<text transform=\"translate(18 {Top + plotH / 2}) rotate(-90)\" text-anchor=\"middle\">{Escape(errorName)}{(y.Log ? " (log)" : "")}</text>\n"));

        double legendY = Top + 10;
        // One series per rigid solver and soft solver (the soft solver only where the scene has soft bodies).
        var series = new List<(SolverType Solver, string Soft)>();
        foreach (SweepPoint p in points) if (!series.Contains((p.Solver, p.SoftSolver))) series.Add((p.Solver, p.SoftSolver));
        foreach ((SolverType solver, string soft) in series)
        {
            var mine = new List<int>();
            for (int i = 0; i < points.Count; i++) if (points[i].Solver == solver && points[i].SoftSolver == soft) mine.Add(i);
            mine.Sort((a, b) => xs[a].CompareTo(xs[b]));
            string colour = soft == "newton" ? NewtonColours[solver] : Colours[solver];
            var line = new StringBuilder();
            foreach (int i in mine) line.Append(Inv($"{Px(xs[i]):F1},{Py(ys[i]):F1} "));
            svg.Append($"<polyline fill=\"none\" stroke=\"{colour}\" stroke-width=\"1.5\" points=\"{line.ToString().TrimEnd()}\"/>\n");
            foreach (int i in mine)
            {
                svg.Append(Inv($"<circle cx=\"{Px(xs[i]):F1}\" cy=\"{Py(ys[i]):F1}\" r=\"3.5\" fill=\"{colour}\"><title>{Describe(points[i])}, error {error(points[i]):G4}</title></circle>\n"));
                svg.Append(Inv($"<text x=\"{Px(xs[i]) + 5:F1}\" y=\"{Py(ys[i]) - 5:F1}\" font-size=\"9\" fill=\"{colour}\">{Setting(points[i])}</text>\n"));
            }
            string name = (solver == SolverType.Pgs ? "PGS" : "TGS") + (soft.Length > 0 ? (soft == "newton" ? ", soft Newton" : ", soft XPBD") : "");
            svg.Append(Inv($"<line x1=\"{Width - Right + 15}\" y1=\"{legendY}\" x2=\"{Width - Right + 40}\" y2=\"{legendY}\" stroke=\"{colour}\" stroke-width=\"2\"/>\n"));
            svg.Append(Inv($"<text x=\"{Width - Right + 46}\" y=\"{legendY + 4}\">{name}</text>\n"));
            legendY += 20;
        }

        var cost = new List<(double, double)>();
        for (int i = 0; i < points.Count; i++) cost.Add((xs[i], ys[i]));
        List<int> front = ParetoFront.Of(cost);
        var stairs = new StringBuilder();
        for (int k = 0; k < front.Count; k++)
        {
            int i = front[k];
            if (k > 0) stairs.Append(Inv($"{Px(xs[i]):F1},{Py(ys[front[k - 1]]):F1} "));
            stairs.Append(Inv($"{Px(xs[i]):F1},{Py(ys[i]):F1} "));
        }
        svg.Append($"<polyline fill=\"none\" stroke=\"#2ca02c\" stroke-width=\"1.5\" stroke-dasharray=\"5 3\" points=\"{stairs.ToString().TrimEnd()}\"/>\n");
        foreach (int i in front)
            svg.Append(Inv($"<circle cx=\"{Px(xs[i]):F1}\" cy=\"{Py(ys[i]):F1}\" r=\"7\" fill=\"none\" stroke=\"#2ca02c\" stroke-width=\"2\"/>\n"));
        svg.Append(Inv($"<circle cx=\"{Width - Right + 27}\" cy=\"{legendY}\" r=\"6\" fill=\"none\" stroke=\"#2ca02c\" stroke-width=\"2\"/>\n"));
        svg.Append(Inv($"<text x=\"{Width - Right + 46}\" y=\"{legendY + 4}\">Pareto front</text>\n"));
        if (clamped)
            svg.Append(Inv($"<text x=\"{Left}\" y=\"{Height - 4}\" font-size=\"10\" fill=\"#666\">an error of 0 is drawn at {Label(floor)}</text>\n"));
        svg.Append("</svg>\n");
        return svg.ToString();
    }

    static string Setting(SweepPoint p) => p.Solver == SolverType.Tgs ? $"{p.Iterations}x{p.Substeps}" : $"{p.Iterations}";

    static string Describe(SweepPoint p) =>
        $"{(p.Solver == SolverType.Pgs ? "pgs" : "tgs")} {p.Iterations} iterations x {p.Substeps} substeps{(p.SoftSolver.Length > 0 ? ", soft " + p.SoftSolver : "")}: {p.MsPerStep:G4} ms/step";

    static string Label(double v) => v.ToString("G3", CultureInfo.InvariantCulture);

    static string Inv(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);

    static string Escape(string s) => s.Replace("&", "&amp;").Replace("<", "&lt;").Replace(">", "&gt;");

    /// <summary>A plot axis over the data's range: log10 when it spans more than a decade.</summary>
    sealed class Axis
    {
        readonly double _lo, _hi;

        public Axis(double[] values)
        {
            double lo = double.MaxValue, hi = double.MinValue;
            foreach (double v in values) { lo = Math.Min(lo, v); hi = Math.Max(hi, v); }
            if (values.Length == 0) { lo = 1; hi = 10; }
            Log = lo > 0 && hi / lo > 10;
            if (Log)
            {
                _lo = Math.Floor(Math.Log10(lo));
                _hi = Math.Ceiling(Math.Log10(hi));
                if (_hi <= _lo) _hi = _lo + 1;
            }
            else
            {
                double pad = hi > lo ? 0.08 * (hi - lo) : Math.Max(Math.Abs(hi) * 0.1, 1e-9);
                _lo = Math.Max(0, lo - pad);
                _hi = hi + pad;
            }
        }

        public bool Log { get; }

        public double Fraction(double v) => ((Log ? Math.Log10(v) : v) - _lo) / (_hi - _lo);

        public IEnumerable<double> Ticks()
        {
            if (Log)
            {
                for (double e = _lo; e <= _hi + 1e-9; e++) yield return Math.Pow(10, e);
                yield break;
            }
            for (int k = 0; k <= 4; k++) yield return _lo + k * (_hi - _lo) / 4;
        }
    }
}
