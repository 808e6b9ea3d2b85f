"""Helpers for the fault tests (tests/cases/faults/<case>, label faults): run
a solver or utility on a variant of a case and assert how it ends.

A variant is a fresh copy of the case's system/ and constant/ (and any other
listed folders) with some files replaced. A refused variant must end with a
FOAM FATAL (IO) ERROR naming the given key words, a non-zero exit code, no
signal (no crash, no stack trace), within a time limit (no hang), and with no
time directory written. An accepted variant must end normally."""
import os
import re
import shutil
import signal
import subprocess
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.environ["DAMPM_PROJECT_DIR"], "tools", "python"))
import dampmPost as dp  # noqa: E402,F401

import numpy as np  # noqa: E402,F401

failures = []

#: Words of a crash: a stack trace (OpenFOAM's signal handlers print one),
#: the C++ runtime's abort (the banner's "Floating point exception trapping"
#: is not one)
crashWords = ("printStack", "#0  Foam::", "Segmentation fault", "terminate called", "core dumped")


def check(ok, what):
    print(("PASS " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def finish():
    if failures:
        print("%d check(s) failed:" % len(failures))
        for f in failures:
            print("  " + f)
        sys.exit(1)
    print("all checks passed")


#: The case's time directories, in time order
timeDirs = dp.times


def makeVariant(name, files=None, copy=("system", "constant"), base="."):
    """A fresh copy of base's folders in variants/<name>, with files
    {path: text or bytes} written over it (None: the file removed)."""
    work = os.path.join("variants", name)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    for d in copy:
        src = os.path.join(base, d)
        if os.path.isdir(src):
            shutil.copytree(src, os.path.join(work, d))
        elif os.path.isfile(src):
            shutil.copy(src, os.path.join(work, d))
    for path, content in (files or {}).items():
        target = os.path.join(work, path)
        if content is None:
            if os.path.isdir(target):
                shutil.rmtree(target)
            elif os.path.exists(target):
                os.remove(target)
            continue
        os.makedirs(os.path.dirname(target) or ".", exist_ok=True)
        with open(target, "wb" if isinstance(content, bytes) else "w") as f:
            f.write(content)
    return work


def run(command, case, log, timeout=300, env=None):
    """Run command (a list) with -case case; returns (status, output).
    status is the exit code, -signal for a signal, or "timeout"."""
    full = list(command) + ["-case", case]
    e = dict(os.environ)
    e.update(env or {})
    try:
        r = subprocess.run(full, capture_output=True, timeout=timeout, env=e)
        status, out = r.returncode, (r.stdout + r.stderr).decode("utf-8", "replace")
    except subprocess.TimeoutExpired as ex:
        status = "timeout"
        out = ((ex.stdout or b"") + (ex.stderr or b"")).decode("utf-8", "replace")
    with open(os.path.join(case, log), "w") as f:
        f.write(out)
    return status, out


def describeStatus(status):
    if status == "timeout":
        return "timed out"
    if isinstance(status, int) and status < 0:
        return "killed by %s" % signal.Signals(-status).name
    return "exit %s" % status


def checkRefused(name, status, out, expected, case=None, written=None):
    """A clear refusal: FOAM FATAL (IO) ERROR, every expected text (a tuple:
    any one of its alternatives), a non-zero exit that is not a signal, no
    crash words; with case, no time directory beyond those in written."""
    check(isinstance(status, int) and status > 0,
          "%s: stops with an error exit code (%s)" % (name, describeStatus(status)))
    fatal = re.search(r"FOAM FATAL (IO )?ERROR", out)
    last = (out.strip().splitlines() or [""])[-1]
    check(bool(fatal), "%s: a FOAM FATAL (IO) ERROR is reported%s"
          % (name, "" if fatal else " (last line: %r)" % last))
    crash = [w for w in crashWords if w in out]
    check(not crash, "%s: no crash (%s)" % (name, ", ".join(crash) if crash else "none"))
    for text in expected:
        alternatives = text if isinstance(text, tuple) else (text,)
        check(any(a in out for a in alternatives),
              "%s: the message names '%s'" % (name, "' or '".join(alternatives)))
    if case is not None:
        dirs = [d for d in timeDirs(case) if d not in (written or [])]
        check(not dirs, "%s: no time directory written (found %s)" % (name, dirs))


def checkAccepted(name, status, out, expected=()):
    """A normal end: exit 0, 'End' in the log, no crash, the expected texts."""
    check(status == 0 and "End" in out, "%s: runs to the end (%s)" % (name, describeStatus(status)))
    crash = [w for w in crashWords if w in out]
    check(not crash, "%s: no crash (%s)" % (name, ", ".join(crash) if crash else "none"))
    for text in expected:
        alternatives = text if isinstance(text, tuple) else (text,)
        check(any(a in out for a in alternatives),
              "%s: the log says '%s'" % (name, "' or '".join(alternatives)))


# Stopped runs and restarts ------------------------------------------------

recordName = "writeComplete"


def application(case):
    text = open(os.path.join(case, "system", "controlDict")).read()
    return re.search(r"^application\s+(\w+);", text, re.M).group(1)


def setControl(path, entry, value):
    """Set a dictionary entry with foamDictionary (a/b for sub-entries)."""
    subprocess.run(["foamDictionary", "-entry", entry, "-set", str(value), path],
                   check=True, capture_output=True)


def newRun(name, base=".", times=(), entries=None):
    """A sub-case with base's system/ and constant/ and the listed time
    directories, with controlDict entries set."""
    work = makeVariant(name, copy=("system", "constant") + tuple(times), base=base)
    for entry, value in (entries or {}).items():
        setControl(os.path.join(work, "system", "controlDict"), entry, value)
    return work


def complete(case, time):
    """Has the time directory its whole record (mpmTime: ending with
    OpenFOAM's end divider)?"""
    path = os.path.join(case, time, "uniform", recordName)
    divider = "// " + "*" * 73 + " //"
    return os.path.isfile(path) and open(path).read().rstrip().endswith(divider)


def start(case, log):
    """Start the case's application in the background."""
    return subprocess.Popen([application(case), "-case", case],
                            stdout=open(os.path.join(case, log), "w"), stderr=subprocess.STDOUT)


def summaryRows(case, solver, startTime="0"):
    """Rows of postProcessing/<solver>/<startTime>/summary.dat (startTime
    None: the latest started), all columns but clockTime."""
    base = os.path.join(case, "postProcessing", solver)
    if startTime is None:
        starts = sorted(os.listdir(base), key=float) if os.path.isdir(base) else []
        if not starts:
            return []
        startTime = starts[-1]
    path = os.path.join(base, startTime, "summary.dat")
    if not os.path.isfile(path):
        return []
    return [l.split()[:-1] for l in open(path) if l.strip() and not l.startswith("#")]


def waitForRows(proc, case, solver, n, timeout=120):
    """Wait until the run has written n summary rows since its start (or
    has ended)."""
    import time
    t0 = time.time()
    while time.time() - t0 < timeout and proc.poll() is None:
        if len(summaryRows(case, solver, None)) >= n:
            return True
        # Short: a test case's whole run can take tens of milliseconds
        time.sleep(0.002)
    return False


def sameFiles(caseA, caseB, time, files, what):
    """The files of a time directory byte for byte the same in two cases."""
    differ = dp.differing_files(os.path.join(caseA, time), os.path.join(caseB, time), files)
    check(not differ, "%s: %s/%s byte for byte those of %s (differ: %s)"
          % (what, caseB, time, caseA, differ or "none"))


def cloudFiles(case, time, cloud):
    d = os.path.join(case, time, "lagrangian", cloud)
    return [os.path.join("lagrangian", cloud, f) for f in sorted(os.listdir(d))]


def exactTime(case, time):
    """The exact value of a time directory (its uniform/time; the name is
    rounded to timePrecision)."""
    text = open(os.path.join(case, time, "uniform", "time")).read()
    return float(re.search(r"^value\s+(\S+);", text, re.M).group(1))


def sameRowsAfter(ref, case, solver, startTime, what):
    """Summary rows after startTime (all but clockTime) the same as ref's."""
    rows = summaryRows(case, solver, startTime)
    t0 = exactTime(case, startTime)
    # Rows print 16 digits: the stop row itself may print a little above t0
    refRows = [r for r in summaryRows(ref, solver) if float(r[0]) > t0 * (1 + 1e-12)]
    check(len(rows) > 0 and rows == refRows,
          "%s: the %d summary rows after %s are those of the uninterrupted run (%d rows)"
          % (what, len(rows), startTime, len(refRows)))
