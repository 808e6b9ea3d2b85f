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
#include "modelConstructor.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::releaseModel> Foam::releaseModel::New
(
    const dictionary& dict,
    const topographyModel& topography,
    const fileName& caseDir
)
{
    const word modelType(dict.get<word>("type"));
    knownKeywords::add(dict, {"type"});

    return autoPtr<releaseModel>
    (
        modelConstructor<releaseModel>(dict, "release type", modelType)
        (dict, topography, caseDir)
    );
}


// ************************************************************************* //
