/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "bedFrictionModel.H"
#include "knownKeywords.H"
#include "modelConstructor.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::bedFrictionModel> Foam::bedFrictionModel::New
(
    const dictionary& dict
)
{
    // Default: a term the case does not select costs nothing
    const word modelType(dict.getOrDefault<word>("bedFriction", "none"));
    knownKeywords::addSelector
    (
        dict, "bedFriction", dictionaryConstructorTablePtr_->sortedToc()
    );

    return autoPtr<bedFrictionModel>
    (
        modelConstructor<bedFrictionModel>(dict, "bedFriction", modelType)
        (dict.optionalSubDict(modelType + "Coeffs"))
    );
}


// ************************************************************************* //
