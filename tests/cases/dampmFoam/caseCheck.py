"""Helpers for the dampmFoam case checks: read the case's output and assert
numbers with a message that states the value, the expectation and the
tolerance."""
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


def summary(case="."):
    return dp.read_dat(os.path.join(case, "postProcessing", "dampmFoam", "0", "summary.dat"))


def cloud(case, time, name):
    return dp.read_field(case, time, name, cloud="dampmCloud")


def positions(case, time):
    path = os.path.join(case, str(time), "lagrangian", "dampmCloud", "positions")
    text = open(path).read()
    n, v = dp._list_after(text, text.index("}") + 1)
    return v.reshape(n, 4)[:, :3]


def finish():
    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)
    print("all checks passed")
