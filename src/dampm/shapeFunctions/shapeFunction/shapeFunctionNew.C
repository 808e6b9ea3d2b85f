/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "shapeFunction.H"
#include "knownKeywords.H"
#include "modelConstructor.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::shapeFunction> Foam::shapeFunction::New
(
    const dictionary& dict,
    const scalar particleHalfWidth
)
{
    const word modelType(dict.get<word>("shapeFunction"));
    knownKeywords::addSelector
    (
        dict, "shapeFunction", dictionaryConstructorTablePtr_->sortedToc()
    );

    return autoPtr<shapeFunction>
    (
        modelConstructor<shapeFunction>(dict, "shapeFunction", modelType)
        (dict.optionalSubDict(modelType + "Coeffs"), particleHalfWidth)
    );
}


// ************************************************************************* //
