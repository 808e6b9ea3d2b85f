#!/usr/bin/python3
"""The energy budget of an elastic block hitting an elastic membrane
(benchmarks/membraneEnergy): at every write time the block's kinetic and
elastic energy (dampmPost.elastic_cloud_energy), the membrane's strain
and kinetic energy (postProcessing/net/0/membrane.dat) and the flow's
potential energy gained since the start (energy.dat; none without
gravity), against what the block brings.

Usage: energyBudget.py <case> <E> <nu> <h>
Prints one line: E_end/E0, the lowest and highest E/E0, the block's x
momentum at the end over its start (-1: a perfect rebound), and the
contact dissipation the code reports over E0."""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.environ["DAMPM_PROJECT_DIR"], "tools", "python"))
import numpy as np  # noqa: E402
import dampmPost as dp  # noqa: E402

case, E, nu, h = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
cloud = "mpm3dCloud"
times = sorted(
    (d for d in os.listdir(case)
     if re.match(r"^[0-9.e+-]+$", d) and os.path.isdir(os.path.join(case, d, "lagrangian", cloud))),
    key=float)
net = dp.read_dat(os.path.join(case, "postProcessing", "net", "0", "membrane.dat"))
flow = dp.read_dat(os.path.join(case, "postProcessing", "mpm3dFoam", "0", "energy.dat"))

total, px = [], []
for t in times:
    eb, p = dp.elastic_cloud_energy(case, t, E, nu, h, cloud)
    j = np.argmin(abs(net["time"] - float(t))) if float(t) > 0 else None
    em = 0.0 if j is None else net["strainEnergy"][j] + net["kineticEnergy"][j]
    # Gravity's work, should a case have any
    k = np.argmin(abs(flow["time"] - float(t)))
    ep = flow["potentialEnergy"][k] - flow["potentialEnergy"][0] if float(t) > 0 else 0.0
    total.append(eb + em + ep)
    px.append(p)
E0 = total[0]
r = np.array(total) / E0
print("%.3f %.3f %.3f %.3f %.4f" % (r[-1], r.min(), r.max(), px[-1] / px[0],
                                    net["contactDissipation"][-1] / E0))
