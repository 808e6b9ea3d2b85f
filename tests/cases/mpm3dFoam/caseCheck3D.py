"""Helpers for the mpm3dFoam case checks: read the case's output (the cloud
mpm3dCloud, postProcessing/mpm3dFoam/0/{summary,energy}.dat and the barriers'
force.dat) and assert numbers with a message that states the value, the
expectation and the tolerance."""
import os
import sys

sys.path.insert(0, os.path.join(os.environ["DAMPM_PROJECT_DIR"], "tools", "python"))
import dampmPost as dp  # noqa: E402,F401

import numpy as np  # noqa: E402

cloudName = "mpm3dCloud"

#: Particle fields mpm3dFoam writes at every write time (besides positions)
fields = ("U", "m", "V", "p", "J", "sigma", "gradU")

failures = []


def check(ok, what):
    print(("PASS " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def near(value, expected, tol, what, relative=False):
    err = abs(value - expected) / (abs(expected) if relative else 1.0)
    check(err <= tol, "%s: %.10g vs %.10g (%s error %.3g, tolerance %.3g)"
          % (what, value, expected, "relative" if relative else "absolute", err, tol))


def summary(case="."):
    """summary.dat: time mass outflowMass kineticEnergy maxSpeed xMin xMax
    yMin yMax zMin zMax nParticles deltaT clockTime"""
    return dp.read_dat(os.path.join(case, "postProcessing", "mpm3dFoam", "0", "summary.dat"))


def energy(case="."):
    """energy.dat: time kineticEnergy potentialEnergy totalEnergy"""
    return dp.read_dat(os.path.join(case, "postProcessing", "mpm3dFoam", "0", "energy.dat"))


def force(case, barrier):
    """force.dat of a barrier: time Fx Fy Fz"""
    return dp.read_dat(os.path.join(case, "postProcessing", barrier, "0", "force.dat"))


def times(case="."):
    """The time directories holding the cloud, in time order (names)."""
    found = []
    for d in os.listdir(case):
        try:
            t = float(d)
        except ValueError:
            continue
        if os.path.isfile(os.path.join(case, d, "lagrangian", cloudName, "positions")):
            found.append((t, d))
    return [d for _, d in sorted(found)]


def cloud(case, time, name):
    """A particle field of the cloud (scalar: N, vector: N x 3, symmTensor:
    N x 6, tensor: N x 9)."""
    return dp.read_field(case, time, name, cloud=cloudName)


def _positions(case, time):
    return dp.read_field(case, time, "positions", cloud=cloudName).reshape(-1, 4)


def positions(case, time):
    """Particle positions (N x 3)."""
    return _positions(case, time)[:, :3]


def cells(case, time):
    """The cell of each particle, the 4th number of a positions entry."""
    return _positions(case, time)[:, 3].astype(int)


def checkFinite(case="."):
    """Every particle field is finite at every write time, and every field
    has one value per particle."""
    for t in times(case):
        p = _positions(case, t)
        ok = bool(np.all(np.isfinite(p)))
        sizes = True
        for name in fields:
            a = cloud(case, t, name)
            ok = ok and bool(np.all(np.isfinite(a)))
            sizes = sizes and len(a) == len(p)
        check(ok, "%s: positions and %s finite at t = %s" % (case, " ".join(fields), t))
        check(sizes, "%s: one value per particle (%d) in every field at t = %s" % (case, len(p), t))


def checkReachedEnd(s, endTime, what):
    """The run of summary.dat s ended at endTime, within half its last step
    (OpenFOAM's Time::run stops once time >= endTime - deltaT/2)"""
    check(s["time"][-1] >= endTime - 0.5 * s["deltaT"][-1],
          "%s: reached endTime %g s within half its last step (%.6f s, step %.3g s)"
          % (what, endTime, s["time"][-1], s["deltaT"][-1]))


def finish():
    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)
    print("all checks passed")
