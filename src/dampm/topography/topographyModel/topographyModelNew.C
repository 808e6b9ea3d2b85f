/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "topographyModel.H"
#include "knownKeywords.H"
#include "modelConstructor.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::topographyModel> Foam::topographyModel::New
(
    const dictionary& dict,
    const fileName& caseDir
)
{
    // Default: flat, which costs nothing
    const word modelType(dict.getOrDefault<word>("topography", "flat"));
    knownKeywords::addSelector
    (
        dict, "topography", dictionaryConstructorTablePtr_->sortedToc()
    );

    autoPtr<topographyModel> model
    (
        modelConstructor<topographyModel>(dict, "topography", modelType)
        (dict.optionalSubDict(modelType + "Coeffs"), caseDir)
    );
    model->byDefault_ = !dict.found("topography");
    return model;
}


// ************************************************************************* //
