/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "discreteDistribution.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"
#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace parameterDistributions
{
    defineTypeNameAndDebug(discreteDistribution, 0);
    addToRunTimeSelectionTable
    (
        parameterDistribution,
        discreteDistribution,
        dictionary
    );
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalarList
Foam::parameterDistributions::discreteDistribution::readValues
(
    const dictionary& dict
)
{
    knownKeywords::add(dict, {"values", "scenarios", "weights"});

    if (dict.found("values") == dict.found("scenarios"))
    {
        FatalIOErrorInFunction(dict)
            << "a discrete distribution needs either values or scenarios;"
            << " allowed: values (v0 v1 ...); or scenarios { name0 { ... }"
            << " name1 { ... } }" << exit(FatalIOError);
    }

    scalarList values;
    if (dict.found("values"))
    {
        values = dict.get<scalarList>("values");
    }
    else
    {
        values.setSize(dict.subDict("scenarios").size());
        forAll(values, i)
        {
            values[i] = i;
        }
    }
    if (values.empty())
    {
        FatalIOErrorInFunction(dict)
            << "a discrete distribution with no values; allowed: at least one"
            << " value or scenario" << exit(FatalIOError);
    }
    for (const scalar v : values)
    {
        if (!std::isfinite(v))
        {
            FatalIOErrorInFunction(dict)
                << "values holds " << v << "; allowed: finite numbers"
                << exit(FatalIOError);
        }
    }
    return values;
}


void Foam::parameterDistributions::discreteDistribution::setCumulative
(
    const dictionary& dict
)
{
    const scalarList weights
    (
        dict.getOrDefault("weights", scalarList(values_.size(), 1.0))
    );
    if (weights.size() != values_.size())
    {
        FatalIOErrorInFunction(dict)
            << "weights has " << weights.size() << " entries for "
            << values_.size() << " values; allowed: one weight per value"
            << exit(FatalIOError);
    }

    cumulative_.setSize(weights.size());
    scalar sum = 0;
    forAll(weights, i)
    {
        if (!(weights[i] >= 0 && std::isfinite(weights[i])))
        {
            FatalIOErrorInFunction(dict)
                << "weights holds " << weights[i] << "; allowed: finite"
                << " weights >= 0 with a sum > 0" << exit(FatalIOError);
        }
        sum += weights[i];
        cumulative_[i] = sum;
    }
    if (!(sum > 0 && std::isfinite(sum)))
    {
        FatalIOErrorInFunction(dict)
            << "the weights sum to " << sum << "; allowed: finite weights >= 0"
            << " with a sum > 0" << exit(FatalIOError);
    }
    for (scalar& c : cumulative_)
    {
        c /= sum;
    }
    last_ = cumulative_.size() - 1;
    while (last_ > 0 && cumulative_[last_ - 1] == cumulative_[last_])
    {
        --last_;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::parameterDistributions::discreteDistribution::discreteDistribution
(
    const dictionary& dict
)
:
    parameterDistribution(dict),
    values_(readValues(dict))
{
    setCumulative(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::parameterDistributions::discreteDistribution::value
(
    const scalar u
) const
{
    const auto k =
        std::upper_bound(cumulative_.begin(), cumulative_.end(), u)
      - cumulative_.begin();
    return values_[std::min(label(k), last_)];
}


// ************************************************************************* //
