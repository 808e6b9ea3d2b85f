/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "boxGeometry.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace barrierGeometries
{
    defineTypeNameAndDebug(boxGeometry, 0);
    addToRunTimeSelectionTable(barrierGeometry, boxGeometry, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::barrierGeometries::boxGeometry::boxGeometry
(
    const word& name,
    const dictionary& dict,
    const fileName& caseDir
)
:
    barrierGeometry(name, dict, caseDir),
    box_(readPoint("min"), readPoint("max"))
{
    knownKeywords::add(dict, {"min", "max"});

    if (!(cmptMin(box_.span()) > 0))
    {
        FatalIOErrorInFunction(dict)
            << "min = " << box_.min() << ", max = " << box_.max() << " are"
            << " invalid; allowed: min < max in every component"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::barrierGeometries::boxGeometry::distance
(
    const pointField& points,
    scalarField& phi,
    vectorField& normal
) const
{
    const point c = box_.centre();
    const vector halfSpan = 0.5*box_.span();
    phi.setSize(points.size());
    normal.setSize(points.size());

    forAll(points, i)
    {
        // q > 0: outside the slab of that axis
        const vector r = points[i] - c;
        vector q, s;
        for (int d = 0; d < 3; ++d)
        {
            q[d] = std::abs(r[d]) - halfSpan[d];
            s[d] = r[d] < 0 ? -1 : 1;
        }
        const scalar qMax = cmptMax(q);
        if (qMax <= 0)
        {
            // Inside: the nearest face
            const int d = q.x() >= q.y()
                ? (q.x() >= q.z() ? 0 : 2)
                : (q.y() >= q.z() ? 1 : 2);
            phi[i] = qMax;
            normal[i] = Zero;
            normal[i][d] = s[d];
        }
        else
        {
            vector out(max(q.x(), 0.0), max(q.y(), 0.0), max(q.z(), 0.0));
            phi[i] = mag(out);
            normal[i] = cmptMultiply(out/phi[i], s);
        }
    }
}


void Foam::barrierGeometries::boxGeometry::describe(Ostream& os) const
{
    os  << "box " << box_.min() << " to " << box_.max();
}


// ************************************************************************* //
