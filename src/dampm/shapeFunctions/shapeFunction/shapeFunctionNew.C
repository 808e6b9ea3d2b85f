/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "shapeFunction.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::shapeFunction> Foam::shapeFunction::New
(
    const dictionary& dict,
    const scalar particleHalfWidth
)
{
    const word modelType(dict.get<word>("shapeFunction"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "shapeFunction",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<shapeFunction>
    (
        cstrIter()(dict.optionalSubDict(modelType + "Coeffs"), particleHalfWidth)
    );
}


// ************************************************************************* //
