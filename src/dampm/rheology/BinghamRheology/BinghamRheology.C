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

const Foam::Enum
<
    Foam::rheologyModels::BinghamRheology::regularisationType
>
Foam::rheologyModels::BinghamRheology::regularisationNames
({
    { regularisationType::Papanastasiou, "Papanastasiou" },
    { regularisationType::biViscous, "biViscous" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rheologyModels::BinghamRheology::BinghamRheology
(
    const dictionary& coeffs
)
:
    NewtonianRheology(coeffs),
    tauY_(readNonNegative("tauY")),
    regularisation_
    (
        regularisationNames.getOrDefault
        (
            "regularisation",
            coeffs,
            regularisationType::Papanastasiou
        )
    ),
    m_(coeffs.getOrDefault<scalar>("m", 100)),
    muMax_(0)
{
    if (!(m_ > 0))
    {
        FatalIOErrorInFunction(coeffs)
            << "m = " << m_ << " is invalid; allowed: m > 0 [s]"
            << exit(FatalIOError);
    }
    if (regularisation_ == regularisationType::biViscous)
    {
        muMax_ = coeffs.get<scalar>("muMax");
        if (!(muMax_ > mu_))
        {
            FatalIOErrorInFunction(coeffs)
                << "muMax = " << muMax_ << " is invalid; allowed: muMax > mu"
                << " = " << mu_ << " [Pa s]" << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::rheologyModels::BinghamRheology::maxViscosity() const
{
    return regularisation_ == regularisationType::biViscous
        ? muMax_
        : mu_ + m_*tauY_;
}


void Foam::rheologyModels::BinghamRheology::stress
(
    const shallowParticles& p
) const
{
    const double mu = mu_;
    const double tauY = tauY_;
    const double m = m_;
    const double muMax = muMax_;

    if (regularisation_ == regularisationType::Papanastasiou)
    {
        // tauY (1 - exp(-m g))/g = tauY m phi(m g), phi(x) = -expm1(-x)/x
        viscousStress
        (
            p,
            [=](const double gammaDot)
            {
                const double x = m*gammaDot;
                const double phi = x > 1e-8 ? -std::expm1(-x)/x : 1 - 0.5*x;
                return mu + tauY*m*phi;
            }
        );
    }
    else
    {
        viscousStress
        (
            p,
            [=](const double gammaDot)
            {
                return gammaDot*muMax > tauY + mu*gammaDot
                    ? mu + tauY/gammaDot
                    : muMax;
            }
        );
    }
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

    const double tauY = tauY_;

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < p.n; ++i)
    {
        p.s[i] += tauY*p.a[i];
    }
}


void Foam::rheologyModels::BinghamRheology::describe(Ostream& os) const
{
    os  << "Bingham (mu = " << mu_ << " Pa s, tauY = " << tauY_ << " Pa, "
        << regularisationNames[regularisation_];
    if (regularisation_ == regularisationType::biViscous)
    {
        os  << " muMax = " << muMax_ << " Pa s";
    }
    else
    {
        os  << " m = " << m_ << " s";
    }
    os  << ", basal shear " << (basalShear_ ? "on" : "off") << ")";
}


// ************************************************************************* //
