#!/usr/bin/python3
"""Write <case>/constant/barLayers, the initialRegions of a bar in its first
axial mode: one box per particle layer along x, with the velocity
U = -v0 sin(pi x/(2 L)) of the layer's centre (towards the end at x = 0, which
stays at rest: the bar is compressed first). initialRegions take a uniform U
per box, and each box holds one layer of the particle lattice, which is at
(i + 1/2) dx/particlesPerCell from the mesh origin.

Usage: barLayers.py <case> <xFirst>: the bar spans xFirst <= x <= L
(xFirst = -L: the free-free bar of length 2 L; 0: the bar against the wall).
"""
import math
import sys

L = 1.0               # length of the fixed-free bar [m]
v0 = 0.1              # velocity amplitude at the free end [m/s]
dx = 0.025            # cell size of system/blockMeshDict [m]
particlesPerCell = 2  # as constant/mpm3dProperties
halfWidth = dx        # square cross-section of 2 x 2 cells about y = z = 0

case, xFirst = sys.argv[1], float(sys.argv[2])
h = dx / particlesPerCell
first, last = round(xFirst / h), round(L / h)
with open(case + "/constant/barLayers", "w") as f:
    f.write("// Written by barLayers.py: %d layers, U = -%g sin(pi x/(2*%g)) m/s\n"
            % (last - first, v0, L))
    for i in range(first, last):
        x = (i + 0.5) * h
        f.write("layer%d { type box; min (%.12g %g %g); max (%.12g %g %g); U (%.15g 0 0); }\n"
                % (i - first, i * h, -halfWidth, -halfWidth, (i + 1) * h, halfWidth, halfWidth,
                   -v0 * math.sin(math.pi * x / (2 * L))))
