/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "NewtonianRheology.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace rheologyModels
{
    defineTypeNameAndDebug(NewtonianRheology, 0);
    addToRunTimeSelectionTable(rheologyModel, NewtonianRheology, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rheologyModels::NewtonianRheology::NewtonianRheology
(
    const dictionary& coeffs
)
:
    rheologyModel(coeffs),
    mu_(readNonNegative("mu")),
    basalShear_(coeffs.getOrDefault<bool>("basalShear", false))
{
    knownKeywords::add(coeffs, {"basalShear"});

    readShearModulus(false);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rheologyModels::NewtonianRheology::stress
(
    const shallowParticles& p,
    const scalar dt
) const
{
    const double mu = mu_;
    viscousStress(p, [mu](double) { return mu; }, G_, dt);
}


void Foam::rheologyModels::NewtonianRheology::addResistance
(
    const shallowParticles& p
) const
{
    if (!basalShear_)
    {
        return;
    }

    // tau_b = 3 mu U/H with U = |v|/sqrt(kappa), H = h sqrt(kappa): the
    // horizontal drag on the column is 3 mu a |v|/(kappa h)
    const double threeMu = 3*mu_;

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < p.n; ++i)
    {
        const double h = p.h[i] > p.hMin ? p.h[i] : p.hMin;
        p.k1[i] += threeMu*p.a[i]/(p.kappa[i]*h);
    }
}


void Foam::rheologyModels::NewtonianRheology::describe(Ostream& os) const
{
    os  << "Newtonian (mu = " << mu_ << " Pa s, ";
    describeStress(os);
    os  << ", basal shear " << (basalShear_ ? "on" : "off") << ")";
}


Foam::yieldViscosity
Foam::rheologyModels::NewtonianRheology::viscosityLaw() const
{
    dictionary coeffs;
    coeffs.add("mu", mu_);
    return yieldViscosity(coeffs, yieldViscosity::lawType::Newtonian);
}


// ************************************************************************* //
