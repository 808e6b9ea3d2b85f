/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "BinghamRheology.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace rheologyModels
{
    defineTypeNameAndDebug(BinghamRheology, 0);
    addToRunTimeSelectionTable(rheologyModel, BinghamRheology, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rheologyModels::BinghamRheology::BinghamRheology
(
    const dictionary& coeffs
)
:
    NewtonianRheology(coeffs),
    viscosity_(coeffs, yieldViscosity::lawType::Bingham)
{
    // Without a yield stress there is no plug: purely viscous by default,
    // the same run as the Newtonian rheology
    readShearModulus(viscosity_.tauY() > 0);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::rheologyModels::BinghamRheology::elastoViscoplastic() const
{
    return G_ > 0 && viscosity_.tauY() > 0;
}


Foam::scalar Foam::rheologyModels::BinghamRheology::maxViscosity() const
{
    // The elastic plug has no viscous limit: the elastic one holds (doc
    // section 9)
    return elastoViscoplastic() ? VGREAT : viscosity_.maxViscosity();
}


void Foam::rheologyModels::BinghamRheology::stress
(
    const shallowParticles& p,
    const scalar dt
) const
{
    if (elastoViscoplastic())
    {
        elastoViscoplasticStress(p, mu_, viscosity_.tauY(), G_, dt);
        return;
    }
    const yieldViscosity muEff(viscosity_);
    viscousStress
    (
        p,
        [&muEff](const double gammaDot) { return muEff(gammaDot); },
        G_,
        dt
    );
}


void Foam::rheologyModels::BinghamRheology::addResistance
(
    const shallowParticles& p
) const
{
    if (!basalShear_)
    {
        return;
    }
    NewtonianRheology::addResistance(p);

    const double tauY = viscosity_.tauY();

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < p.n; ++i)
    {
        p.s[i] += tauY*p.a[i];
    }
}


void Foam::rheologyModels::BinghamRheology::describe(Ostream& os) const
{
    os  << "Bingham (";
    if (elastoViscoplastic())
    {
        // The regularisation is not used
        os  << "mu = " << mu_ << " Pa s, tauY = " << viscosity_.tauY()
            << " Pa, elasto-viscoplastic stress, G = " << G_ << " Pa";
    }
    else
    {
        viscosity_.describe(os);
        os  << ", ";
        describeStress(os);
    }
    os  << ", basal shear " << (basalShear_ ? "on" : "off") << ")";
}


// ************************************************************************* //
