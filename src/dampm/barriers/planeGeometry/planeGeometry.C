/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "planeGeometry.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace barrierGeometries
{
    defineTypeNameAndDebug(planeGeometry, 0);
    addToRunTimeSelectionTable(barrierGeometry, planeGeometry, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::barrierGeometries::planeGeometry::planeGeometry
(
    const word& name,
    const dictionary& dict,
    const fileName& caseDir
)
:
    barrierGeometry(name, dict, caseDir),
    origin_(readPoint("point")),
    normal_(readDirection("normal"))
{
    knownKeywords::add(dict, {"point", "normal"});
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::barrierGeometries::planeGeometry::distance
(
    const pointField& points,
    scalarField& phi,
    vectorField& normal
) const
{
    phi = (points - origin_) & normal_;
    normal = vectorField(points.size(), normal_);
}


void Foam::barrierGeometries::planeGeometry::describe(Ostream& os) const
{
    os  << "plane through " << origin_ << " with normal " << normal_;
}


// ************************************************************************* //
