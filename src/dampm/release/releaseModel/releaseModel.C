/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "releaseModel.H"
#include "knownKeywords.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(releaseModel, 0);
    defineRunTimeSelectionTable(releaseModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::releaseModel::releaseModel
(
    const dictionary& dict,
    const topographyModel& topography,
    const fileName& caseDir
)
:
    dict_(dict),
    topography_(topography),
    caseDir_(caseDir),
    U_(dict.getOrDefault<vector2D>("U", vector2D::zero))
{
    knownKeywords::add(dict, {"U"});
}


// ************************************************************************* //
