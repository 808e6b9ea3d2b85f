"""What accuracy costs in time, depth-averaged part: the metrics, table and
plots shared by benchmarks/accuracyVsTime/ritter and .../mangeney.

Each sub-study's Allrun runs dampmFoam and shallowWaterFoam one case after
the other and appends a line per run to <work>/runs.dat:

    solver shape ppc co nx dx wallTime cpuTime case

(co: the Courant number of the time step; wallTime: elapsed seconds of the
solver alone, cpuTime: its user + system seconds). Its accuracyTable script describes the problem (a Problem below)
and calls study(), which reads each case's h at the end time, computes

- L1: sum |h - h_exact| dx / (h0 L) over the compared part of the channel,
  of length L, at the field's points (dampmFoam: the grid nodes of the point
  field h; shallowWaterFoam: the cell centres of its cell field h);
- front: (x_f - x_f,exact) / (x_f,exact - x_dam), where x_f is the most
  downstream point with h > 1 % of h0, interpolated linearly to the 1 %
  crossing between it and the next point, for the computed and for the exact
  solution alike,

and writes results.md, metrics.dat and the plots l1VsTime.png,
frontVsTime.png into the output directory.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ["DAMPM_PROJECT_DIR"], "tools", "python"))
import dampmPost as dp  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FRONT_LEVEL = 0.01          # the front is where h crosses 1 % of h0
THRESHOLDS = (0.05, 0.01, 0.001)


# Exact solutions ------------------------------------------------------------

def ritter(xi, h0, g):
    """Dry-bed dam break (Ritter, 1892) at similarity coordinate
    xi = (x - x_dam)/t: height."""
    c0 = math.sqrt(g * h0)
    xi = np.asarray(xi, dtype=float)
    h = np.where(xi <= -c0, h0, (2 * c0 - xi) ** 2 / (9 * g))
    return np.where(xi >= 2 * c0, 0.0, h)


def stokerState(h0, h1, g):
    """Wet-bed dam break (Stoker, 1957), still layer h1 downstream: the
    height h2 and speed u2 between the rarefaction and the bore, and the bore
    speed s. h2 solves 2 (c0 - c2) = (h2 - h1) sqrt(g (h2 + h1) / (2 h1 h2))
    (the Riemann invariant through the rarefaction equals the speed behind
    the bore from its mass and momentum balance); bisection."""
    c0 = math.sqrt(g * h0)

    def f(h2):
        return 2 * (c0 - math.sqrt(g * h2)) \
            - (h2 - h1) * math.sqrt(g * (h2 + h1) / (2 * h1 * h2))

    lo, hi = h1, h0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if f(mid) > 0:
            lo = mid
        else:
            hi = mid
    h2 = 0.5 * (lo + hi)
    u2 = 2 * (c0 - math.sqrt(g * h2))
    return h2, u2, h2 * u2 / (h2 - h1)


def stoker(xi, h0, h1, g):
    """Wet-bed dam break at xi = (x - x_dam)/t: height."""
    c0 = math.sqrt(g * h0)
    h2, u2, s = stokerState(h0, h1, g)
    xi = np.asarray(xi, dtype=float)
    h = np.where(xi <= -c0, h0, (2 * c0 - xi) ** 2 / (9 * g))
    h = np.where(xi > u2 - math.sqrt(g * h2), h2, h)
    return np.where(xi > s, h1, h)


def frontSimilarity(h0, g, h1=0.0):
    """xi = (x - x_dam)/t of the exact 1 % front: in the rarefaction
    (2 c0 - xi)^2 = 9 g 0.01 h0, i.e. xi = 1.7 c0, unless a bore higher than
    1 % of h0 stands in front of that (wet bed), then the bore."""
    c0 = math.sqrt(g * h0)
    xi = 2 * c0 - 3 * math.sqrt(g * FRONT_LEVEL * h0)
    if h1 > 0:
        h2, u2, s = stokerState(h0, h1, g)
        if h2 > FRONT_LEVEL * h0:
            xi = s
    return xi


class Problem:
    """One dam break: h0, the dam at xDam, gravity g (the pressure gravity),
    the end time t, and the compared part (xMin, xMax) of the channel, all in
    the frame of dampmFoam's output. frameShift: shallowWaterFoam's cases run
    in a frame moving by frameShift along x at time t (0 for Ritter; a t^2/2
    on the incline). exactDampm(x): the exact h in dampmFoam's frame."""

    def __init__(self, name, title, h0, xDam, g, t, xMin, xMax, exactDampm, frameShift=0.0,
                 layer=0.0):
        self.name, self.title = name, title
        self.h0, self.xDam, self.g, self.t = h0, xDam, g, t
        self.xMin, self.xMax = xMin, xMax
        self.exactDampm = exactDampm
        self.frameShift = frameShift
        self.layer = layer

    def exact(self, solver, x):
        """Exact h at dampmFoam-frame x for a solver's run: the dry bed for
        dampmFoam, Stoker's wet bed with shallowWaterFoam's layer."""
        if solver == "shallowWaterFoam":
            return stoker((x - self.frameShift - self.xDam) / self.t, self.h0, self.layer, self.g)
        return self.exactDampm(x)

    def exactFront(self, solver):
        h1 = self.layer if solver == "shallowWaterFoam" else 0.0
        xi = frontSimilarity(self.h0, self.g, h1)
        return self.xDam + self.frameShift + xi * self.t


# Reading the runs -------------------------------------------------------------

def readRuns(work):
    runs = []
    with open(os.path.join(work, "runs.dat")) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            solver, shape, ppc, co, nx, dx, wall, cpu, case = line.split()
            runs.append(dict(solver=solver, shape=shape, ppc=int(ppc) if ppc != "-" else 0, co=float(co), nx=int(nx),
                             dx=float(dx), wall=float(wall), cpu=float(cpu), case=case))
    return runs


def readFailed(work):
    """Runs of work/failed.dat (runs that stopped), with the last time they
    reached (lastTime, "-" when none) and infinite errors."""
    path = os.path.join(work, "failed.dat")
    if not os.path.isfile(path):
        return []
    failed = []
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        f = line.split()
        failed.append(dict(solver=f[0], shape=f[1], ppc=int(f[2]) if f[2] != "-" else 0, co=float(f[3]),
                           nx=int(f[4]), dx=float(f[5]), wall=float(f[6]), cpu=float(f[7]), case=f[8],
                           lastTime=f[9] if len(f) > 9 else "-", l1=float("inf"), front=float("inf")))
    return failed


def profile(run, problem):
    """(x, h) along the channel at the end time, x in dampmFoam's frame:
    dampmFoam's grid nodes on one line of the mesh (the channel is uniform
    across), shallowWaterFoam's cell centres."""
    case, time = run["case"], dp.latest_time(run["case"])
    if abs(float(time) - problem.t) > 1e-6:
        raise RuntimeError("%s: last time %s, expected %g (the run did not finish)" % (case, time, problem.t))
    pts = dp.read_points(case)
    h = dp.read_field(case, time, "h")
    if run["solver"] == "dampmFoam":
        line = (np.abs(pts[:, 1] - np.median(pts[:, 1])) < 1e-9) & (pts[:, 2] == pts[:, 2].min())
        o = np.argsort(pts[line, 0])
        return pts[line, 0][o], h[line][o]
    xs = np.unique(pts[:, 0])
    xc = 0.5 * (xs[1:] + xs[:-1])
    if len(xc) != len(h):
        raise RuntimeError("%s: %d cells along x, %d values of h" % (case, len(xc), len(h)))
    return xc + problem.frameShift, h


def frontOf(x, h, level):
    """Most downstream crossing of h = level, linear between the last point
    above it and the next one."""
    above = np.nonzero(h > level)[0]
    if len(above) == 0:
        return float("nan")
    k = above.max()
    if k + 1 >= len(x):
        return float(x[k])
    return float(x[k] + (h[k] - level) / (h[k] - h[k + 1]) * (x[k + 1] - x[k]))


def metrics(run, problem):
    x, h = profile(run, problem)
    if not np.all(np.isfinite(h)):
        raise RuntimeError("%s: non-finite h" % run["case"])
    he = problem.exact(run["solver"], x)
    sel = (x > problem.xMin) & (x <= problem.xMax)
    dx = x[1] - x[0]
    l1 = float(np.sum(np.abs(h[sel] - he[sel])) * dx / (problem.h0 * (problem.xMax - problem.xMin)))
    xf = frontOf(x, h, FRONT_LEVEL * problem.h0)
    xfe = problem.exactFront(run["solver"])
    return l1, (xf - xfe) / (xfe - problem.xDam), xf - xfe


# Table, orders, cheapest settings, plots ---------------------------------------

def seriesKey(r):
    return (r["solver"], r["shape"], r["ppc"], r["co"])


def seriesLabel(key):
    solver, shape, ppc, co = key
    if solver == "shallowWaterFoam":
        return "shallowWaterFoam, Co %g" % co
    return "%s, %d ppc, Co %g" % (shape, ppc, co)


def order(rows, metric):
    """Slope of log(error) against log(dx), least squares (NaN with fewer
    than 3 resolutions or a zero error)."""
    dx = np.array([r["dx"] for r in rows])
    e = np.array([abs(r[metric]) for r in rows])
    if len(rows) < 3 or np.any(e <= 0):
        return float("nan")
    return float(np.polyfit(np.log(dx), np.log(e), 1)[0])


def fmtOrder(p):
    return "-" if math.isnan(p) else "%.2f" % p


def fmtTime(s):
    return "%.2f" % s if s < 10 else "%.1f" % s


def setting(r):
    what = "%d cells (dx %g m), Co %g" % (r["nx"], r["dx"], r["co"])
    if r["solver"] == "dampmFoam":
        what = "%s, %d ppc, %s" % (r["shape"], r["ppc"], what)
    return what


def cost(r):
    """Order of the cheapest: wall time, then the coarser grid, then the
    series (ties resolved the same way on every run)."""
    return (r["wall"], -r["dx"], seriesKey(r))


def cheapest(runs, metric, tol, solver):
    """The least wall time of a solver's runs with |error| <= tol, else the
    best error reached."""
    pool = [r for r in runs if r["solver"] == solver]
    if not pool:
        return "no run completed"
    ok = [r for r in pool if abs(r[metric]) <= tol]
    if ok:
        r = min(ok, key=cost)
        return "%s: %s s (%+.2g %%)" % (setting(r), fmtTime(r["wall"]), 100 * r[metric])
    best = min(pool, key=lambda r: abs(r[metric]))
    return "none reached (best %+.2g %%: %s, %s s)" % (100 * best[metric], setting(best), fmtTime(best["wall"]))


def cheapestStaying(runs, failed, metric, tol, solver):
    """The least wall time of a solver's runs from which every finer grid of
    the same series also has |error| <= tol (a lucky crossing of a sign
    change does not count, nor does a failed run), else "none". A run on
    the finest grid has no finer grid to stay on: it is marked so."""
    found = []
    for key in sorted({seriesKey(r) for r in runs if r["solver"] == solver}):
        rows = sorted([r for r in runs + failed if seriesKey(r) == key], key=lambda r: r["dx"], reverse=True)
        for k in range(len(rows)):
            if all(abs(r[metric]) <= tol for r in rows[k:]):
                found.append(rows[k])
                break
    if not found:
        return "none"
    r = min(found, key=cost)
    finest = min(x["dx"] for x in runs + failed if x["solver"] == solver)
    return "%s: %s s%s" % (setting(r), fmtTime(r["wall"]), " (finest grid only)" if r["dx"] == finest else "")


def orderedSeries(runs):
    """The series of the runs: dampmFoam's first, by Courant number, shape
    and ppc, then shallowWaterFoam's."""
    return sorted({seriesKey(r) for r in runs}, key=lambda k: (k[0] != "dampmFoam", k[3], k[1], k[2]))


def plot(runs, metric, ylabel, path, title):
    keys = orderedSeries(runs)
    many = len(keys) > 12
    fig, ax = plt.subplots(figsize=(10.5, 5.5) if many else (7.5, 5))
    colours = {"quadraticBSpline": "tab:blue", "GIMP": "tab:orange", "linear": "tab:green"}
    markers = {1: "v", 2: "o", 3: "s", 4: "D"}
    styles = ("-", "--", "-.", (0, (1, 1)))  # (the tolerances' lines are dotted)
    courants = sorted({r["co"] for r in runs})
    for key in keys:
        rows = sorted([r for r in runs if seriesKey(r) == key], key=lambda r: r["dx"], reverse=True)
        t = [r["wall"] for r in rows]
        e = [max(abs(r[metric]), 1e-5) for r in rows]
        style = styles[courants.index(key[3]) % len(styles)]
        if key[0] == "shallowWaterFoam":
            ax.loglog(t, e, color="k", linestyle=style, marker="x", lw=2, ms=8, label=seriesLabel(key))
        else:
            ax.loglog(t, e, linestyle=style, color=colours.get(key[1], "tab:grey"), marker=markers.get(key[2], "^"),
                      ms=5, lw=1, alpha=0.85, label=seriesLabel(key))
    for tol in THRESHOLDS:
        ax.axhline(tol, color="grey", lw=0.7, ls=":")
    ax.set_xlabel("wall time of the solver run [s]")
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    ax.grid(True, which="both", lw=0.3)
    if many:
        # (beside the axes: the series fill them)
        ax.legend(fontsize=6, ncol=1, loc="center left", bbox_to_anchor=(1.01, 0.5))
    else:
        ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def study(problem, work, out, note):
    """Metrics of every run in work/runs.dat; results.md, metrics.dat and
    the plots into out. note: markdown describing the problem and the
    comparison, put before the table."""
    runs = readRuns(work)
    for r in runs:
        r["l1"], r["front"], r["frontMetres"] = metrics(r, problem)

    with open(os.path.join(out, "metrics.dat"), "w") as f:
        f.write("# %s: one line per run; wallTime [s] elapsed, cpuTime [s] user+system\n" % problem.title)
        f.write("# front: relative to the distance travelled; frontMetres: x_f - x_f,exact [m]\n")
        f.write("# co: Courant number of the time step\n")
        f.write("# solver shape ppc co nx dx wallTime cpuTime L1 front frontMetres\n")
        for r in runs:
            f.write("%s %s %d %g %d %.6g %.4f %.4f %.6e %.6e %.6e\n" % (
                r["solver"], r["shape"], r["ppc"], r["co"], r["nx"], r["dx"], r["wall"], r["cpu"], r["l1"],
                r["front"], r["frontMetres"]))

    plot(runs, "l1", "L1 error of h / (h0 L)", os.path.join(out, "l1VsTime.png"), problem.title + ": L1 error")
    plot(runs, "front", "|front error| / distance travelled", os.path.join(out, "frontVsTime.png"),
         problem.title + ": 1 % front")

    failed = readFailed(work)
    keys = orderedSeries(runs)
    lines = ["## %s" % problem.title, "", note, "",
             "| solver | shape | ppc | Co | cells | dx [m] | wall time [s] | CPU time [s] | L1 | front error |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for key in keys:
        for r in sorted([r for r in runs if seriesKey(r) == key], key=lambda r: r["dx"], reverse=True):
            lines.append("| %s | %s | %s | %g | %d | %g | %s | %s | %.2e | %+.2f %% |" % (
                r["solver"], r["shape"] if r["solver"] == "dampmFoam" else "-",
                r["ppc"] if r["solver"] == "dampmFoam" else "-", r["co"], r["nx"], r["dx"], fmtTime(r["wall"]),
                fmtTime(r["cpu"]), r["l1"], 100 * r["front"]))
    lines += ["", "Observed orders of convergence (least-squares slope of log error against log dx, per series;"
              " the front from |front error|):", "",
              "| series | L1 order | front order |", "|---|---|---|"]
    for key in keys:
        rows = [r for r in runs if seriesKey(r) == key]
        lines.append("| %s | %s | %s |" % (seriesLabel(key), fmtOrder(order(rows, "l1")), fmtOrder(order(rows, "front"))))
    lines += ["", "Cheapest setting (least wall time) that reaches each error; below it, the cheapest from which every"
              " finer grid of the same series stays within it (the front error changes sign with dx, so a single"
              " run can meet a tolerance by luck):", "",
              "| metric | error | dampmFoam | shallowWaterFoam |", "|---|---|---|---|"]
    for metric, name in (("l1", "L1"), ("front", "front")):
        for tol in THRESHOLDS:
            lines.append("| %s | %g %% | %s | %s |" % (name, 100 * tol, cheapest(runs, metric, tol, "dampmFoam"),
                                                       cheapest(runs, metric, tol, "shallowWaterFoam")))
            lines.append("| | and stays | %s | %s |" % (cheapestStaying(runs, failed, metric, tol, "dampmFoam"),
                                                       cheapestStaying(runs, failed, metric, tol,
                                                                       "shallowWaterFoam")))
    if failed:
        lines += ["", "Runs that failed (not in the table, the fits or the plots):", ""]
        for f in failed:
            lines.append("- %s, %s: stopped at t = %s s after %s s (log: %s)"
                         % (f["solver"], setting(f), f["lastTime"], fmtTime(f["wall"]), os.path.basename(f["case"])))
    lines += ["", "![L1 error against wall time](l1VsTime.png)", "",
              "![front error against wall time](frontVsTime.png)", ""]
    with open(os.path.join(out, "results.md"), "w") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))
    return runs
