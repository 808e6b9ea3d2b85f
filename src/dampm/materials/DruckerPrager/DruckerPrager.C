/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "DruckerPrager.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace materialModels
{
    defineTypeNameAndDebug(DruckerPrager, 0);
    addToRunTimeSelectionTable(materialModel, DruckerPrager, dictionary);
}
}


const Foam::materialModel::coeffRange
Foam::materialModels::DruckerPrager::angleRange
{
    0, true, 90, false, "deg"
};


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::materialModels::DruckerPrager::DruckerPrager(const dictionary& coeffs)
:
    linearElastic(coeffs),
    phi_(readCoeff("frictionAngle", angleRange)),
    psi_(readCoeffOrDefault("dilatancyAngle", 0, angleRange)),
    cohesion_(readCoeffOrDefault("cohesion", 0, stressRange)),
    alpha_(0),
    alphaPsi_(0),
    k_(0),
    plasticStrain_(-1)
{
    if (!(psi_ <= phi_))
    {
        FatalIOErrorInFunction(coeffs)
            << "frictionAngle = " << phi_ << ", dilatancyAngle = " << psi_
            << " are invalid; allowed: 0 <= dilatancyAngle <= frictionAngle"
            << " < 90 [deg]" << exit(FatalIOError);
    }
    const scalar deg = constant::mathematical::pi/180;
    const scalar tp = std::tan(phi_*deg);
    const scalar tq = std::tan(psi_*deg);
    alpha_ = tp/std::sqrt(9 + 12*tp*tp);
    alphaPsi_ = tq/std::sqrt(9 + 12*tq*tq);
    k_ = 3*cohesion_/std::sqrt(9 + 12*tp*tp);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::materialModels::DruckerPrager::addFields(particleArrays& particles)
{
    plasticStrain_ = particles.addField
    (
        "plasticStrain",
        particleArrays::fieldKind::scalar
    );
}


void Foam::materialModels::DruckerPrager::updateStress
(
    particleArrays& particles,
    const materialParticles& mp,
    const scalar dt
) const
{
    typedef materialParticles::tensor3 tensor3;
    double* epsP = particles.component(plasticStrain_);
    const double alpha = alpha_, alphaPsi = alphaPsi_, k = k_;
    const double G = G_, K = K_;

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < mp.n; ++i)
    {
        tensor3 sigma = trialStress(mp, i, dt);
        const double I1 = sigma.trace();
        tensor3 s = materialParticles::dev(sigma);
        const double sqrtJ2 = std::sqrt(0.5*s.squaredNorm());
        const double f = alpha*I1 + sqrtJ2 - k;

        if (f > 0)
        {
            // Return to the cone along the potential's gradient
            const double dLambda = f/(9*K*alpha*alphaPsi + G);
            const double I1new = I1 - 9*K*alphaPsi*dLambda;
            const double sqrtJ2new = sqrtJ2 - G*dLambda;
            if (sqrtJ2new > 0 && !(alpha > 0 && I1new > k/alpha))
            {
                s *= sqrtJ2new/sqrtJ2;
                sigma = s;
                sigma.diagonal().array() += I1new/3;
                epsP[i] += dLambda;
            }
            else
            {
                // Apex: hydrostatic at the cone's tip. The whole trial
                // deviator is plastic, sqrt(J2)/G of equivalent shear
                // strain; the cone's dLambda overshoots the tip
                sigma.setZero();
                sigma.diagonal().array() +=
                    alpha > 0 ? k/(3*alpha) : I1/3;
                epsP[i] += sqrtJ2/G;
            }
        }
        mp.setStress(i, sigma);
    }
}


void Foam::materialModels::DruckerPrager::describe(Ostream& os) const
{
    os  << "DruckerPrager (rho = " << rho_ << " kg/m^3, E = " << E_
        << " Pa, nu = " << nu_ << ", friction angle " << phi_
        << " deg, dilatancy angle " << psi_ << " deg, cohesion " << cohesion_
        << " Pa, volumetric smoothing "
        << (volumetricSmoothing_ ? "on" : "off") << ")";
}


// ************************************************************************* //
