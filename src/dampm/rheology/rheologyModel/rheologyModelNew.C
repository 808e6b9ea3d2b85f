/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "rheologyModel.H"
#include "knownKeywords.H"
#include "modelConstructor.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::rheologyModel> Foam::rheologyModel::New
(
    const dictionary& dict
)
{
    // Default: a term the case does not select costs nothing
    const word modelType(dict.getOrDefault<word>("rheology", "inviscid"));
    knownKeywords::addSelector
    (
        dict, "rheology", dictionaryConstructorTablePtr_->sortedToc()
    );

    return autoPtr<rheologyModel>
    (
        modelConstructor<rheologyModel>(dict, "rheology", modelType)
        (dict.optionalSubDict(modelType + "Coeffs"))
    );
}


// ************************************************************************* //
