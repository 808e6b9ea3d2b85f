/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "noBedFriction.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bedFrictionModels
{
    defineTypeNameAndDebug(noBedFriction, 0);
    addToRunTimeSelectionTable(bedFrictionModel, noBedFriction, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bedFrictionModels::noBedFriction::noBedFriction(const dictionary& coeffs)
:
    bedFrictionModel(coeffs)
{
    knownKeywords::add(coeffs, {});
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bedFrictionModels::noBedFriction::addResistance
(
    const shallowParticles& p
) const
{}


void Foam::bedFrictionModels::noBedFriction::describe(Ostream& os) const
{
    os  << "none (no basal friction computed)";
}


// ************************************************************************* //
