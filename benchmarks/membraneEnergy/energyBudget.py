#!/usr/bin/python3
"""The energy budget of an elastic block hitting an elastic membrane
(benchmarks/membraneEnergy): at every write time the energy the bodies and
the contact hold, E (dampmPost.membrane_energy_budget: the block's kinetic
and elastic, the membrane's strain and kinetic, the contact's push, the
flow's potential energy gained), and what the contact reports dissipated,
D, against what the block brings, E0.

Usage: energyBudget.py <case> <E> <nu> <h> [rigid]
(rigid: the case has a rigid wall in place of the membrane)
Prints one line: E_end/E0, the lowest and highest E/E0, the block's x
momentum at the end over its start (-1: a perfect rebound), D_end/E0, and
the lowest and highest (E + D)/E0."""
import os
import sys

sys.path.insert(0, os.path.join(os.environ["DAMPM_PROJECT_DIR"], "tools", "python"))
import dampmPost as dp  # noqa: E402

case, E, nu, h = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
rigid = len(sys.argv) > 5 and sys.argv[5] == "rigid"
t, held, dissipated, px = dp.membrane_energy_budget(case, E, nu, h, None if rigid else "net")
E0 = held[0]
r = held / E0
rd = (held + dissipated) / E0
print("%.3f %.3f %.3f %.3f %.4f %.3f %.3f" % (r[-1], r.min(), r.max(), px[-1] / px[0],
                                              dissipated[-1] / E0, rd.min(), rd.max()))
