/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "CoulombFriction.H"
#include "boundedScalar.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bedFrictionModels
{
    defineTypeNameAndDebug(CoulombFriction, 0);
    addToRunTimeSelectionTable(bedFrictionModel, CoulombFriction, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bedFrictionModels::CoulombFriction::CoulombFriction
(
    const dictionary& coeffs
)
:
    bedFrictionModel(coeffs),
    tanPhi_(tan(readFrictionAngle()*constant::mathematical::pi/180)),
    pA_(coeffs.getOrDefault<scalar>("pA", 0))
{
    knownKeywords::add(coeffs, {"pA"});

    boundedScalar(coeffs, "pA", pA_, scalarBound::nonNegative, "[Pa]");
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bedFrictionModels::CoulombFriction::addResistance
(
    const shallowParticles& p
) const
{
    const double tanPhi = tanPhi_;
    const double pAtanPhi = pA_*tanPhi_;
    const double g = p.g;

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < p.n; ++i)
    {
        p.s[i] += p.kappa[i]*p.m[i]*g*tanPhi + pAtanPhi*p.a[i];
    }
}


void Foam::bedFrictionModels::CoulombFriction::describe(Ostream& os) const
{
    os  << "Coulomb (tan(phi) = " << tanPhi_ << ", pA = " << pA_ << " Pa)";
}


// ************************************************************************* //
