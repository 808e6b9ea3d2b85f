"""Helpers for the mpm3dFoam case checks: read the case's output and assert
numbers with a message that states the value, the expectation and the
tolerance (the assertions of ../dampmFoam/caseCheck.py, for cloud
mpm3dCloud)."""
import os
import sys

sys.path.insert(0, os.path.join(os.environ["DAMPM_PROJECT_DIR"], "tests", "cases", "dampmFoam"))
from caseCheck import check, near, finish, dp, np  # noqa: E402,F401


def summary(case="."):
    return dp.read_dat(os.path.join(case, "postProcessing", "mpm3dFoam", "0", "summary.dat"))


def energy(case="."):
    return dp.read_dat(os.path.join(case, "postProcessing", "mpm3dFoam", "0", "energy.dat"))


def cloud(case, time, name):
    return dp.read_field(case, time, name, cloud="mpm3dCloud")


def positions(case, time):
    path = os.path.join(case, str(time), "lagrangian", "mpm3dCloud", "positions")
    text = open(path).read()
    n, v = dp._list_after(text, text.index("}") + 1)
    return v.reshape(n, 4)[:, :3]
