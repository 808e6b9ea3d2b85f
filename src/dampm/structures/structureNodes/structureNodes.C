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
#include <cmath>

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


void Foam::structureNodes::pairAcross
(
    const scalar yLo,
    const scalar yHi,
    const scalar tol,
    const dictionary& dict
)
{
    const label n = size();
    const char* const allowed =
        "; allowed on a plane slice: a strip across the slice's thickness,"
        " one element across, its nodes on the slice's faces in twins at the"
        " same x and z (geometry: e.g. a panel with two corners at each"
        " face; ropes: one on each face)";
    twin.assign(n, -1);
    std::vector<char> onFace(n);
    for (label i = 0; i < n; ++i)
    {
        const bool onLo = std::abs(y0[i] - yLo) <= tol;
        if (!onLo && std::abs(y0[i] - yHi) > tol)
        {
            FatalIOErrorInFunction(dict)
                << "node " << i << " at " << referencePosition(i)
                << " lies on neither face of the plane slice, y = " << yLo
                << " and y = " << yHi << allowed << exit(FatalIOError);
        }
        onFace[i] = onLo ? 0 : 1;
    }
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n && twin[i] < 0 && onFace[i] == 0; ++j)
        {
            if
            (
                onFace[j] == 1 && twin[j] < 0
             && std::abs(x0[j] - x0[i]) <= tol
             && std::abs(z0[j] - z0[i]) <= tol
            )
            {
                twin[i] = j;
                twin[j] = i;
            }
        }
    }
    for (label i = 0; i < n; ++i)
    {
        const label j = twin[i];
        if (j < 0)
        {
            FatalIOErrorInFunction(dict)
                << "node " << i << " at " << referencePosition(i)
                << " has no twin on the plane slice's other face" << allowed
                << exit(FatalIOError);
        }
        if (fixed[i] != fixed[j])
        {
            FatalIOErrorInFunction(dict)
                << "node " << i << " at " << referencePosition(i)
                << (fixed[i] ? " is" : " is not") << " anchored, its twin "
                << j << " at " << referencePosition(j)
                << (fixed[j] ? " is" : " is not") << "; allowed on a plane"
                << " slice: anchors that hold both twins or neither (anchors:"
                << " a box across the slice's thickness)" << exit(FatalIOError);
        }
        if (j > i)
        {
            // The twin at the node's x and z; the pair's mass halved
            x0[j] = x[j] = x0[i];
            z0[j] = z[j] = z0[i];
            mass[i] = mass[j] = 0.5*(mass[i] + mass[j]);
        }
    }
}


void Foam::structureNodes::tieTwins()
{
    const label n = label(twin.size());
    for (label i = 0; i < n; ++i)
    {
        const label j = twin[i];
        if (j < i)
        {
            continue;
        }
        for (std::vector<double>* f : {&fx, &fz, &fExtX, &fExtZ})
        {
            const double mean = 0.5*((*f)[i] + (*f)[j]);
            (*f)[i] = (*f)[j] = mean;
        }
        fy[i] = fy[j] = fExtY[i] = fExtY[j] = 0;
    }
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
