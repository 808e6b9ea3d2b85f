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
#include <cmath>
#include <limits>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(parameterDistribution, 0);
    defineRunTimeSelectionTable(parameterDistribution, dictionary);
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::Pair<Foam::scalar> Foam::parameterDistribution::readBounds
(
    const dictionary& dict,
    const bool required
)
{
    knownKeywords::add(dict, {"min", "max"});

    constexpr scalar inf = std::numeric_limits<scalar>::infinity();
    const scalar lower =
        required ? dict.get<scalar>("min") : dict.getOrDefault("min", -inf);
    const scalar upper =
        required ? dict.get<scalar>("max") : dict.getOrDefault("max", inf);

    for (const word key : {"min", "max"})
    {
        const scalar bound = key == "min" ? lower : upper;
        if (dict.found(key) && !std::isfinite(bound))
        {
            FatalIOErrorInFunction(dict)
                << key << " = " << bound << " is invalid; allowed: a finite "
                << key << exit(FatalIOError);
        }
    }
    if (!(lower < upper))
    {
        FatalIOErrorInFunction(dict)
            << "min = " << lower << " and max = " << upper << " are invalid;"
            << " allowed: min < max" << exit(FatalIOError);
    }
    return Pair<scalar>(lower, upper);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::parameterDistribution::parameterDistribution(const dictionary& dict)
:
    dict_(dict)
{}


// ************************************************************************* //
