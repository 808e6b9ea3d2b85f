/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "VoellmyFriction.H"
#include "boundedScalar.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bedFrictionModels
{
    defineTypeNameAndDebug(VoellmyFriction, 0);
    addToRunTimeSelectionTable(bedFrictionModel, VoellmyFriction, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bedFrictionModels::VoellmyFriction::VoellmyFriction
(
    const dictionary& coeffs
)
:
    CoulombFriction(coeffs),
    xi_(coeffs.get<scalar>("xi"))
{
    knownKeywords::add(coeffs, {"xi"});

    boundedScalar(coeffs, "xi", xi_, scalarBound::positive, "[m/s^2]");
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bedFrictionModels::VoellmyFriction::addResistance
(
    const shallowParticles& p
) const
{
    CoulombFriction::addResistance(p);

    // Turbulent drag along the surface: speed^2 = |v|^2/kappa
    const double rhoGbyXi = p.rho*p.g/xi_;

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < p.n; ++i)
    {
        p.k2[i] += rhoGbyXi*p.a[i]/p.kappa[i];
    }
}


void Foam::bedFrictionModels::VoellmyFriction::describe(Ostream& os) const
{
    os  << "Voellmy (xi = " << xi_ << " m/s^2) with ";
    CoulombFriction::describe(os);
}


// ************************************************************************* //
