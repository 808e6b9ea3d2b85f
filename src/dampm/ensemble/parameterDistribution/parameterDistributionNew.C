/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "parameterDistribution.H"
#include "knownKeywords.H"
#include "modelConstructor.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::parameterDistribution> Foam::parameterDistribution::New
(
    const dictionary& dict
)
{
    const word distributionType(dict.get<word>("distribution"));
    knownKeywords::add(dict, {"distribution"});

    return autoPtr<parameterDistribution>
    (
        modelConstructor<parameterDistribution>
        (
            dict, "distribution", distributionType
        )(dict)
    );
}


// ************************************************************************* //
