/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "inviscidRheology.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace rheologyModels
{
    defineTypeNameAndDebug(inviscidRheology, 0);
    addToRunTimeSelectionTable(rheologyModel, inviscidRheology, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rheologyModels::inviscidRheology::inviscidRheology
(
    const dictionary& coeffs
)
:
    rheologyModel(coeffs)
{
    knownKeywords::add(coeffs, {});
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rheologyModels::inviscidRheology::stress
(
    const shallowParticles& p,
    const scalar dt
) const
{
    viscousStress(p, [](double) { return 0.0; }, 0, dt);
}


void Foam::rheologyModels::inviscidRheology::describe(Ostream& os) const
{
    os  << "inviscid (no stress computed)";
}


Foam::yieldViscosity
Foam::rheologyModels::inviscidRheology::viscosityLaw() const
{
    dictionary coeffs;
    coeffs.add("mu", 0.0);
    return yieldViscosity(coeffs, yieldViscosity::lawType::Newtonian);
}


// ************************************************************************* //
