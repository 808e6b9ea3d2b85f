"""The decomposition dampm runs with: each processor one box of the
structured grid. For N processors the grid is cut into n = (nx ny nz)
boxes, nx ny nz = N (nz = 1 on a 2D grid, one cell thick), as square (or
cubic) as possible, of near-equal cell counts along each axis (whether or
not N divides them); decomposePar takes the cut as method manual
(constant/cellDecomposition)."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import dampmPost as dp  # noqa: E402


def cell_counts(case):
    """Cells of the case's uniform blockMesh grid along x, y and z."""
    pts = dp.read_points(case)
    return [len(np.unique(np.round(pts[:, k], 9))) - 1 for k in range(3)]


def split(counts, nProcs):
    """(nx, ny, nz) with nx ny nz = nProcs and at least three cells per box
    along each axis cut, the boxes as square as possible along x, y (and z on a
    3D grid); x cut first, then y, on a tie."""
    axes = 3 if counts[2] > 1 else 2
    best = None
    for nx in range(nProcs, 0, -1):
        for ny in range(nProcs // nx, 0, -1):
            nz = nProcs // (nx * ny)
            n = (nx, ny, nz)
            # at least three cells along a cut: a particle's stencil reaches
            # two nodes beyond its cell
            if nx * ny * nz != nProcs or any(n[d] > 1 and counts[d] // n[d] < 3 for d in range(3)):
                continue
            sizes = [counts[d] / n[d] for d in range(axes)]
            aspect = max(sizes) / min(sizes)
            if best is None or aspect < best[0]:
                best = (aspect, n)
    return None if best is None else best[1]


def owners(counts, n):
    """The processor of every cell (blockMesh order: x fastest, then y,
    then z)."""
    cut = [np.arange(counts[d]) * n[d] // counts[d] for d in range(3)]
    return (cut[0][None, None, :] + n[0] * (cut[1][None, :, None] + n[1] * cut[2][:, None, None])).ravel()


HEADER = """/*--------------------------------*- C++ -*----------------------------------*\\
  dampm | Material Point Method for landslide run-out and barrier impact
  Not approved or endorsed by OpenCFD Limited, owner of the OpenFOAM trademark.
\\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       %s;
    object      %s;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

"""

DICT = """// Written by tools/python/decomposition.py: %(nProcs)d boxes, n (%(n)s), of
// the %(cells)s grid (dampm runs on boxes of the grid only)
numberOfSubdomains  %(nProcs)d;
method              manual;
coeffs
{
    dataFile    "cellDecomposition";
}

// ************************************************************************* //
"""


def write_dict(case, nProcs):
    counts = cell_counts(case)
    n = split(counts, nProcs)
    if n is None:
        sys.exit("decomposition: %d processors cannot each hold a box of the %s cells of %s"
                 % (nProcs, " x ".join(map(str, counts)), case))
    cells = owners(counts, n)
    with open(os.path.join(case, "constant", "cellDecomposition"), "w") as f:
        f.write(HEADER % ("labelList", "cellDecomposition"))
        f.write("%d\n(\n%s\n)\n" % (cells.size, "\n".join(map(str, cells))))
    with open(os.path.join(case, "system", "decomposeParDict"), "w") as f:
        f.write(HEADER % ("dictionary", "decomposeParDict"))
        f.write(DICT % {"nProcs": nProcs, "n": " ".join(map(str, n)),
                        "cells": " x ".join(map(str, counts if counts[2] > 1 else counts[:2]))})
    print("system/decomposeParDict: %d processors, boxes n (%s) of the %s cells"
          % (nProcs, " ".join(map(str, n)), " x ".join(map(str, counts if counts[2] > 1 else counts[:2]))))


if __name__ == "__main__":
    write_dict(sys.argv[2] if len(sys.argv) > 2 else ".", int(sys.argv[1]))
