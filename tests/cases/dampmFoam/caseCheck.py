"""Helpers for the dampmFoam case checks: read the case's output and assert
numbers with a message that states the value, the expectation and the
tolerance."""
import filecmp
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ["DAMPM_PROJECT_DIR"], "tools", "python"))
import dampmPost as dp  # noqa: E402,F401

import numpy as np  # noqa: E402

failures = []


def check(ok, what):
    print(("PASS " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def near(value, expected, tol, what, relative=False):
    err = abs(value - expected) / (abs(expected) if relative else 1.0)
    check(err <= tol, "%s: %.10g vs %.10g (%s error %.3g, tolerance %.3g)"
          % (what, value, expected, "relative" if relative else "absolute", err, tol))


def summary(case=".", start="0"):
    return dp.read_dat(os.path.join(case, "postProcessing", "dampmFoam", start, "summary.dat"))


def cloud(case, time, name):
    return dp.read_field(case, time, name, cloud="dampmCloud")


def positions(case, time):
    return dp.cloud_positions(case, time, "dampmCloud")


def cellSize(case="."):
    """Smallest cell side [m] of the case's uniform blockMesh grid, from
    constant/polyMesh/points."""
    pts = dp.read_points(case)
    sides = []
    for k in (0, 1):
        steps = np.diff(np.unique(pts[:, k]))
        if np.ptp(steps) > 1e-9 * steps.max():
            raise ValueError("%s: the grid is not uniform in %s" % (case, "xy"[k]))
        sides.append(steps.mean())
    return min(sides)


def frontRadii(case, time, centre, nSectors):
    """Distance of the farthest column from centre in each of nSectors equal
    sectors of direction."""
    p = positions(case, time)
    r = np.hypot(p[:, 0] - centre[0], p[:, 1] - centre[1])
    sector = ((np.arctan2(p[:, 1] - centre[1], p[:, 0] - centre[0]) + np.pi)
              * nSectors / (2 * np.pi)).astype(int) % nSectors
    radii = np.zeros(nSectors)
    np.maximum.at(radii, sector, r)
    return radii


def checkRadialFront(case, centre, wallDistance, nSectors=32):
    """The front stays radially symmetric while it is clear of the sides: at
    every written time at which the farthest column is more than two cells
    (the B-spline reach) from them, the front radius varies over nSectors
    directions by less than one cell, the size read from the case's mesh.
    Returns the number of times checked."""
    dx = cellSize(case)
    checked = 0
    for t in dp.times(case):
        if float(t) == 0:
            continue
        radii = frontRadii(case, t, centre, nSectors)
        if radii.max() > wallDistance - 2 * dx:
            break
        spread = radii.max() - radii.min()
        check(spread < dx, "t = %s s: front radius %.3f to %.3f m over %d directions, spread %.4f m < one cell %.4g m"
              % (t, radii.min(), radii.max(), nSectors, spread, dx))
        checked += 1
    return checked


def differingFiles(a, b):
    """The files of directory trees a and b that differ byte for byte, that
    only one holds, or that cannot be compared, as paths relative to them"""
    found = []

    def walk(c, prefix):
        found.extend(prefix + f for f in c.left_only + c.right_only + c.funny_files)
        _, mismatch, errors = filecmp.cmpfiles(c.left, c.right, c.common_files, shallow=False)
        found.extend(prefix + f for f in mismatch + errors)
        for name, sub in c.subdirs.items():
            walk(sub, prefix + name + "/")
    walk(filecmp.dircmp(a, b), "")
    return found


def finish():
    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)
    print("all checks passed")
