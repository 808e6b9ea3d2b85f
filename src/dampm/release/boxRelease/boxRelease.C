/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "boxRelease.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace releaseModels
{
    defineTypeNameAndDebug(boxRelease, 0);
    addToRunTimeSelectionTable(releaseModel, boxRelease, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::releaseModels::boxRelease::boxRelease
(
    const dictionary& dict,
    const topographyModel& topography,
    const fileName& caseDir
)
:
    polygonRelease(dict, topography, caseDir, false)
{
    knownKeywords::add(dict, {"min", "max"});

    const vector2D lo(dict.get<vector2D>("min"));
    const vector2D hi(dict.get<vector2D>("max"));
    if (!(hi.x() > lo.x() && hi.y() > lo.y()))
    {
        FatalIOErrorInFunction(dict)
            << "release box min " << lo << " max " << hi << " is empty;"
            << " allowed: max > min in x and y" << exit(FatalIOError);
    }
    setPolygon
    (
        List<vector2D>
        ({
            lo, vector2D(hi.x(), lo.y()), hi, vector2D(lo.x(), hi.y())
        })
    );
}


// ************************************************************************* //
