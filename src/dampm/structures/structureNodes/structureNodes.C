/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "structureNodes.H"
#include "structureInput.H"
#include "exactPrecision.H"
#include "vectorField.H"
#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The vectors of three component arrays
Foam::vectorField joined
(
    const std::vector<double>& cx,
    const std::vector<double>& cy,
    const std::vector<double>& cz
)
{
    Foam::vectorField v(Foam::label(cx.size()));
    forAll(v, i)
    {
        v[i] = Foam::vector(cx[i], cy[i], cz[i]);
    }
    return v;
}


//- Entry keyword of state, one vector per node, into three arrays
void readSplit
(
    const Foam::dictionary& state,
    const Foam::word& keyword,
    std::vector<double>& cx,
    std::vector<double>& cy,
    std::vector<double>& cz
)
{
    const Foam::vectorField v(state.get<Foam::vectorField>(keyword));
    Foam::structureInput::checkSize
    (
        state, keyword, v.size(), Foam::label(cx.size()), "one per node"
    );
    forAll(v, i)
    {
        cx[i] = v[i].x();
        cy[i] = v[i].y();
        cz[i] = v[i].z();
    }
}

} // End anonymous namespace


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


void Foam::structureNodes::writeState(dictionary& state) const
{
    // An entry keeps its value as printed when it is set
    const exactPrecision exact;
    state.set("positions", joined(x, y, z));
    state.set("velocities", joined(vx, vy, vz));
    state.set("internalForces", joined(fx, fy, fz));
    state.set("externalForces", joined(fExtX, fExtY, fExtZ));
}


void Foam::structureNodes::readState(const dictionary& state)
{
    readSplit(state, "positions", x, y, z);
    readSplit(state, "velocities", vx, vy, vz);
    readSplit(state, "internalForces", fx, fy, fz);
    readSplit(state, "externalForces", fExtX, fExtY, fExtZ);
}


// ************************************************************************* //
