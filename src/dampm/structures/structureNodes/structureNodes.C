/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "structureNodes.H"
#include <algorithm>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::structureNodes::append(const point& p)
{
    for (std::vector<double>* v : {&x0, &x})
    {
        v->push_back(p.x());
    }
    for (std::vector<double>* v : {&y0, &y})
    {
        v->push_back(p.y());
    }
    for (std::vector<double>* v : {&z0, &z})
    {
        v->push_back(p.z());
    }
    for
    (
        std::vector<double>* v
      : {&vx, &vy, &vz, &fx, &fy, &fz, &fExtX, &fExtY, &fExtZ, &mass}
    )
    {
        v->push_back(0);
    }
    fixed.push_back(0);
    return size() - 1;
}


Foam::label Foam::structureNodes::nearest
(
    const point& p,
    scalar& distance
) const
{
    label best = -1;
    scalar best2 = GREAT;
    for (label nodei = 0; nodei < size(); ++nodei)
    {
        const scalar d2 = magSqr(referencePosition(nodei) - p);
        if (d2 < best2)
        {
            best2 = d2;
            best = nodei;
        }
    }
    distance = best < 0 ? GREAT : std::sqrt(best2);
    return best;
}


void Foam::structureNodes::clearExternalForces()
{
    std::fill(fExtX.begin(), fExtX.end(), 0.0);
    std::fill(fExtY.begin(), fExtY.end(), 0.0);
    std::fill(fExtZ.begin(), fExtZ.end(), 0.0);
}


// ************************************************************************* //
