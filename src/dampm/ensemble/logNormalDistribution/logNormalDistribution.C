/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "logNormalDistribution.H"
#include "boundedScalar.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"
#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace parameterDistributions
{
    defineTypeNameAndDebug(logNormalDistribution, 0);
    addToRunTimeSelectionTable
    (
        parameterDistribution,
        logNormalDistribution,
        dictionary
    );
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::parameterDistributions::logNormalDistribution::readMedian
(
    const dictionary& dict
)
{
    return boundedScalar
    (
        dict, "median", dict.get<scalar>("median"), scalarBound::positive
    );
}


Foam::Pair<Foam::scalar>
Foam::parameterDistributions::logNormalDistribution::readLogBounds
(
    const dictionary& dict
)
{
    const Pair<scalar> bounds(readBounds(dict, false));
    for (const word key : {"min", "max"})
    {
        if (dict.found(key))
        {
            const scalar bound = key == "min" ? bounds.first() : bounds.second();
            boundedScalar(dict, key, bound, scalarBound::positive);
        }
    }
    // log(-inf) is NaN: no lower bound is ln(0) = -inf
    return Pair<scalar>
    (
        dict.found("min") ? std::log(bounds.first()) : bounds.first(),
        std::log(bounds.second())
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::parameterDistributions::logNormalDistribution::logNormalDistribution
(
    const dictionary& dict
)
:
    normalDistribution
    (
        dict,
        std::log(readMedian(dict)),
        "logStandardDeviation",
        dict.get<scalar>("logStandardDeviation"),
        readLogBounds(dict)
    )
{
    knownKeywords::add(dict, {"median", "logStandardDeviation"});
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::parameterDistributions::logNormalDistribution::value
(
    const scalar u
) const
{
    return std::exp(normalDistribution::value(u));
}


// ************************************************************************* //
