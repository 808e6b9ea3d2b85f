/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "normalDistribution.H"
#include "standardNormal.H"
#include "boundedScalar.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"
#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace parameterDistributions
{
    defineTypeNameAndDebug(normalDistribution, 0);
    addToRunTimeSelectionTable
    (
        parameterDistribution,
        normalDistribution,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::parameterDistributions::normalDistribution::normalDistribution
(
    const dictionary& dict,
    const scalar mean,
    const word& sdKeyword,
    const scalar standardDeviation,
    const Pair<scalar>& bounds
)
:
    parameterDistribution(dict),
    mean_(mean),
    standardDeviation_
    (
        boundedScalar(dict, sdKeyword, standardDeviation, scalarBound::positive)
    ),
    zMin_((bounds.first() - mean)/standardDeviation),
    zMax_((bounds.second() - mean)/standardDeviation)
{
    if (!std::isfinite(mean))
    {
        FatalIOErrorInFunction(dict)
            << "the mean " << mean << " is invalid; allowed: a finite mean"
            << exit(FatalIOError);
    }
    const scalar p = standardNormal::probability(zMin_, zMax_);
    if (!(p >= minProbability))
    {
        FatalIOErrorInFunction(dict)
            << "min and max leave a probability of " << p << " (standard"
            << " scores " << zMin_ << " to " << zMax_ << "); allowed: bounds"
            << " that hold a probability of at least " << minProbability
            << " of the untruncated distribution" << exit(FatalIOError);
    }
}


Foam::parameterDistributions::normalDistribution::normalDistribution
(
    const dictionary& dict
)
:
    normalDistribution
    (
        dict,
        dict.get<scalar>("mean"),
        "standardDeviation",
        dict.get<scalar>("standardDeviation"),
        readBounds(dict, false)
    )
{
    knownKeywords::add(dict, {"mean", "standardDeviation"});
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::parameterDistributions::normalDistribution::value
(
    const scalar u
) const
{
    return
        mean_
      + standardDeviation_*standardNormal::truncatedQuantile(u, zMin_, zMax_);
}


// ************************************************************************* //
