/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "uniformDistribution.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace parameterDistributions
{
    defineTypeNameAndDebug(uniformDistribution, 0);
    addToRunTimeSelectionTable
    (
        parameterDistribution,
        uniformDistribution,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::parameterDistributions::uniformDistribution::uniformDistribution
(
    const dictionary& dict
)
:
    parameterDistribution(dict),
    bounds_(readBounds(dict, true))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::parameterDistributions::uniformDistribution::value
(
    const scalar u
) const
{
    return bounds_.first() + u*(bounds_.second() - bounds_.first());
}


// ************************************************************************* //
