/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "nodeIncidence.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::nodeIncidence::nodeIncidence
(
    const std::vector<label>& slotNode,
    const label nNodes
)
:
    start_(nNodes + 1, 0),
    slot_(slotNode.size())
{
    // Counting sort of the slots by node: slots stay in increasing order
    for (const label nodei : slotNode)
    {
        ++start_[nodei + 1];
    }
    for (label nodei = 0; nodei < nNodes; ++nodei)
    {
        start_[nodei + 1] += start_[nodei];
    }
    std::vector<label> next(start_.begin(), start_.end() - 1);
    for (label sloti = 0; sloti < label(slotNode.size()); ++sloti)
    {
        slot_[next[slotNode[sloti]]++] = sloti;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::nodeIncidence::gatherAdd
(
    const std::vector<double>& slotForce,
    std::vector<double>& fx,
    std::vector<double>& fy,
    std::vector<double>& fz
) const
{
    const label nNodes = label(start_.size()) - 1;

    #pragma omp parallel for schedule(static)
    for (label nodei = 0; nodei < nNodes; ++nodei)
    {
        double sx = 0, sy = 0, sz = 0;
        for (label k = start_[nodei]; k < start_[nodei + 1]; ++k)
        {
            const double* f = &slotForce[3*slot_[k]];
            sx += f[0];
            sy += f[1];
            sz += f[2];
        }
        fx[nodei] += sx;
        fy[nodei] += sy;
        fz[nodei] += sz;
    }
}


// ************************************************************************* //
