/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "materialModel.H"
#include "knownKeywords.H"
#include "modelConstructor.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::materialModel> Foam::materialModel::New
(
    const dictionary& dict
)
{
    const word modelType(dict.get<word>("material"));
    knownKeywords::addSelector
    (
        dict, "material", dictionaryConstructorTablePtr_->sortedToc()
    );

    return autoPtr<materialModel>
    (
        modelConstructor<materialModel>(dict, "material", modelType)
        (dict.optionalSubDict(modelType + "Coeffs"))
    );
}


// ************************************************************************* //
