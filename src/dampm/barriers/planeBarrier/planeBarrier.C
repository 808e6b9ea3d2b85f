/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "planeBarrier.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace barrierModels
{
    defineTypeNameAndDebug(planeBarrier, 0);
    addToRunTimeSelectionTable(barrierModel, planeBarrier, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::barrierModels::planeBarrier::planeBarrier
(
    const word& name,
    const dictionary& dict,
    const fileName& caseDir
)
:
    barrierModel(name, dict, caseDir),
    origin_(readPoint("point")),
    normal_(readDirection("normal"))
{
    knownKeywords::add(dict, {"point", "normal"});
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::barrierModels::planeBarrier::distance
(
    const pointField& points,
    scalarField& phi,
    vectorField& normal
) const
{
    phi = (points - origin_) & normal_;
    normal = vectorField(points.size(), normal_);
}


void Foam::barrierModels::planeBarrier::describeGeometry(Ostream& os) const
{
    os  << "plane through " << origin_ << " with normal " << normal_;
}


// ************************************************************************* //
