"""Shared checks of the stability suite (tests/cases/stability/*/check): the
hard cases of both solvers assert the same three things, finite fields,
conservation and a physical bound, so the reading and asserting is here once.

It builds on the case-check helpers of the two solvers (caseCheck.py for
dampmFoam, caseCheck3D.py for mpm3dFoam), whose failures go to one list, so
that check(), near() and finish() work for either.

A "run" is a case directory: the case itself (".") or a sub-case that the
Allrun made (threads1, restart, ...). Every function takes it first."""
import os
import sys

sys.dont_write_bytecode = True
_cases = os.path.join(os.environ["DAMPM_PROJECT_DIR"], "tests", "cases")
sys.path.insert(0, os.path.join(_cases, "mpm3dFoam"))
sys.path.insert(0, os.path.join(_cases, "dampmFoam"))
import caseCheck as cc2  # noqa: E402
import caseCheck3D as cc3  # noqa: E402

import numpy as np  # noqa: E402

dp = cc2.dp
# One list of failures for the checks of both helper modules
cc3.failures = cc2.failures
check = cc2.check
checkReachedEnd = cc3.checkReachedEnd
near = cc2.near
finish = cc2.finish

g = 9.81

#: The clouds and time-series directories of the two solvers
clouds = {"dampmFoam": "dampmCloud", "mpm3dFoam": "mpm3dCloud"}


# -- Reading -------------------------------------------------------------------

def summary(run=".", solver="dampmFoam", start="0"):
    """summary.dat of a run started at time start. dampmFoam: time mass
    outflowMass kineticEnergy maxSpeed xMin xMax yMin yMax nParticles deltaT
    clockTime; mpm3dFoam adds zMin zMax."""
    return dp.read_dat(os.path.join(run, "postProcessing", solver, str(start), "summary.dat"))


def energy3D(run=".", start="0"):
    """energy.dat of mpm3dFoam: time kineticEnergy potentialEnergy totalEnergy"""
    return dp.read_dat(os.path.join(run, "postProcessing", "mpm3dFoam", str(start), "energy.dat"))


def times(run, solver="dampmFoam"):
    """The time directories of a run that hold its cloud, in time order."""
    found = []
    for d in os.listdir(run):
        try:
            t = float(d)
        except ValueError:
            continue
        if os.path.isfile(os.path.join(run, d, "lagrangian", clouds[solver], "positions")):
            found.append((t, d))
    return [d for _, d in sorted(found)]


def positions(run, time, solver="dampmFoam"):
    """Particle positions (N x 3) of the cloud at a write time."""
    return (cc2.positions if solver == "dampmFoam" else cc3.positions)(run, time)


def cloud(run, time, name, solver="dampmFoam"):
    return dp.read_field(run, time, name, cloud=clouds[solver])


def cloudFields(run, time, solver="dampmFoam"):
    """Every particle field written at a time: dict name -> array."""
    path = os.path.join(run, str(time), "lagrangian", clouds[solver])
    out = {}
    for name in sorted(os.listdir(path)):
        if name == "positions" or not os.path.isfile(os.path.join(path, name)):
            continue
        out[name] = cloud(run, time, name, solver)
    return out


# -- Finite fields -------------------------------------------------------------

def checkFinite(run=".", solver="dampmFoam", start="0"):
    """Every column of summary.dat at every step, and positions and every
    particle field at every write time, are finite (no NaN, no inf), with
    one value per particle."""
    s = summary(run, solver, start)
    bad = [k for k, v in s.items() if not np.all(np.isfinite(v))]
    check(not bad, "%s: every summary.dat column finite at all %d steps%s"
          % (run, len(s["time"]), " (not: %s)" % " ".join(bad) if bad else ""))
    written = times(run, solver)
    for t in written:
        p = positions(run, t, solver)
        fields = cloudFields(run, t, solver)
        badFields = [k for k, v in fields.items() if not np.all(np.isfinite(v))]
        sizes = all(len(v) == len(p) for v in fields.values())
        check(np.all(np.isfinite(p)) and not badFields and sizes,
              "%s: t = %s: positions and %d particle fields (%s) finite, one value per particle (%d)%s"
              % (run, t, len(fields), " ".join(fields), len(p),
                 " (not: %s)" % " ".join(badFields) if badFields else ""))
    return s


# -- Conservation --------------------------------------------------------------

#: Relative round-off allowed for mass plus outflow: sums of up to 1e5
#: positive masses in double precision, and the 12 digits summary.dat keeps
massTol = 1e-11


def checkMass(run=".", solver="dampmFoam", start="0", M0=None, tol=massTol):
    """Mass plus outflow equals the initial mass at every step (relative
    tol), the mass in the domain never grows, and the outflow never shrinks.
    M0: the initial mass (default: the first row's mass plus outflow)."""
    s = summary(run, solver, start)
    total = s["mass"] + s["outflowMass"]
    if M0 is None:
        M0 = total[0]
    err = np.max(np.abs(total - M0)) / M0
    check(err <= tol, "%s: mass + outflow = initial mass %.10g kg at every step: largest relative error %.3g <= %.3g"
          % (run, M0, err, tol))
    check(np.all(np.diff(s["mass"]) <= tol * M0) and np.all(np.diff(s["outflowMass"]) >= 0),
          "%s: the mass in the domain never grows, the outflow never shrinks" % run)
    return s


def initialMass(run=".", solver="dampmFoam", time="0"):
    """Mass of the cloud written at a time (the release), summed in sorted
    order."""
    return float(np.sum(np.sort(cloud(run, time, "m", solver))))


# -- Bounds --------------------------------------------------------------------

def checkBelow(values, bound, what):
    """Every value at most bound; the message states the largest."""
    v = np.asarray(values)
    check(np.all(v <= bound), "%s: largest %.6g <= %.6g" % (what, np.max(v) if v.size else 0.0, bound))


def checkAtRest(run=".", solver="dampmFoam", start="0", after=0.0, vMax=1e-6):
    """From time after on, the largest particle speed of every step is below
    vMax [m/s]; returns the number of steps checked."""
    s = summary(run, solver, start)
    late = s["time"] >= after - 1e-12
    checkBelow(s["maxSpeed"][late], vMax, "%s: max speed [m/s] at each of %d steps from t = %g s"
               % (run, np.sum(late), after))
    return int(np.sum(late))


def checkNoCreep(run, t1, t2, tol, solver="dampmFoam"):
    """The particles written at t1 and t2 are the same, at the same places
    to tol [m] (matched by sorting: stored order may change on re-binning)."""
    p1, p2 = positions(run, t1, solver), positions(run, t2, solver)
    if len(p1) != len(p2):
        check(False, "%s: same particles at t = %s and %s (%d vs %d)" % (run, t1, t2, len(p1), len(p2)))
        return
    d = np.max(np.abs(sortRows(p1) - sortRows(p2))) if len(p1) else 0.0
    check(d <= tol, "%s: no creep from t = %s to %s s: largest displacement %.3g m <= %.3g m"
          % (run, t1, t2, d, tol))


def checkCourant(run=".", solver="dampmFoam", start="0", dx=None, maxCo=0.4, waveSpeed=0.0, slack=1e-9):
    """Every step kept (maxSpeed + waveSpeed) deltaT / dx <= maxCo, with the
    speed at the start of the step (the previous row of summary.dat: the
    step is set from it). waveSpeed 0: the kinematic part of dampmFoam's
    limit (its wave part sqrt(g h) adds to the speed, so this is necessary;
    flat beds, where the speed along the bed is the horizontal one); the
    material's constant wave speed: mpm3dFoam's limit itself. Returns the
    largest."""
    s = summary(run, solver, start)
    co = (s["maxSpeed"][:-1] + waveSpeed) * s["deltaT"][1:] / dx
    largest = np.max(co) if co.size else 0.0
    check(np.all(co <= maxCo * (1 + slack)), "%s: (maxSpeed + %g m/s) deltaT/dx <= maxCo %.3g (+%.3g) at every step (largest %.6g)"
          % (run, waveSpeed, maxCo, slack, largest))
    return largest


def sortRows(p):
    """Rows of p in lexicographic order (columns x, y[, z]) after rounding
    to 1e-9 of the extent: the same particles, stored in any order."""
    scale = np.max(np.abs(p)) + 1
    keys = [np.round(p[:, k] / scale, 9) for k in reversed(range(p.shape[1]))]
    return p[np.lexsort(keys)]


def sameState(runA, runB, time, names, tol, solver="dampmFoam", what=""):
    """Positions and the named particle fields of two runs at a write time
    agree to relative tol (0: bit for bit), matched by position."""
    pa, pb = positions(runA, time, solver), positions(runB, time, solver)
    if len(pa) != len(pb):
        check(False, "%s and %s: same number of particles at t = %s (%d vs %d)"
              % (runA, runB, time, len(pa), len(pb)))
        return
    scale = np.max(np.abs(pa)) + 1
    ka = [np.round(pa[:, k] / scale, 7) for k in reversed(range(3))]
    kb = [np.round(pb[:, k] / scale, 7) for k in reversed(range(3))]
    oa, ob = np.lexsort(ka), np.lexsort(kb)
    d = np.max(np.abs(pa[oa] - pb[ob])) / scale
    check(d <= tol, "%s vs %s at t = %s%s: positions agree, largest relative difference %.3g <= %.3g"
          % (runA, runB, time, what, d, tol))
    for name in names:
        a, b = cloud(runA, time, name, solver)[oa], cloud(runB, time, name, solver)[ob]
        ref = np.max(np.abs(a)) or 1.0
        d = np.max(np.abs(a - b)) / ref
        check(d <= tol, "%s vs %s at t = %s%s: %s agrees, largest relative difference %.3g <= %.3g"
              % (runA, runB, time, what, name, d, tol))


def identicalFiles(runA, runB, time, names, solver="dampmFoam"):
    """The cloud files of two runs at a write time are identical, byte for
    byte (the same run on another number of threads)."""
    base = os.path.join(str(time), "lagrangian", clouds[solver])
    for name in names:
        a = open(os.path.join(runA, base, name), "rb").read()
        b = open(os.path.join(runB, base, name), "rb").read()
        check(a == b, "%s and %s: %s/%s identical, byte for byte" % (runA, runB, base, name))


def checkHorizontalSpeed(run, bound, what, solver="dampmFoam"):
    """The largest horizontal particle speed at every write time is at most
    bound [m/s] (the cloud's U; dampmFoam writes U with the vertical
    component along the bed, which is dropped here)."""
    worst = 0.0
    for t in times(run, solver):
        U = cloud(run, t, "U", solver)
        worst = max(worst, float(np.max(np.hypot(U[:, 0], U[:, 1]))) if len(U) else 0.0)
    checkBelow([worst], bound, "%s: horizontal speed [m/s] at all %d write times, %s"
               % (run, len(times(run, solver)), what))
    return worst
