/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "viscoplasticFluid.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace materialModels
{
    typedef fluidMaterial<yieldViscosity::lawType::Newtonian> NewtonianFluid;
    typedef fluidMaterial<yieldViscosity::lawType::Bingham> BinghamFluid;
    typedef fluidMaterial<yieldViscosity::lawType::HerschelBulkley>
        HerschelBulkleyFluid;

    defineTemplateTypeNameAndDebugWithName(NewtonianFluid, "Newtonian", 0);
    defineTemplateTypeNameAndDebugWithName(BinghamFluid, "Bingham", 0);
    defineTemplateTypeNameAndDebugWithName
    (
        HerschelBulkleyFluid,
        "HerschelBulkley",
        0
    );

    addToRunTimeSelectionTable(materialModel, NewtonianFluid, dictionary);
    addToRunTimeSelectionTable(materialModel, BinghamFluid, dictionary);
    addToRunTimeSelectionTable
    (
        materialModel,
        HerschelBulkleyFluid,
        dictionary
    );
}
}


const Foam::materialModel::coeffRange
Foam::materialModels::viscoplasticFluid::soundSpeedRange
{
    1e-3, true, 1e5, true, "m/s"
};


const Foam::materialModel::coeffRange
Foam::materialModels::viscoplasticFluid::exponentRange
{
    1, true, 100, true, ""
};


const Foam::materialModel::coeffRange
Foam::materialModels::viscoplasticFluid::pressureCutRange
{
    -1e13, true, 0, true, "Pa"
};


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::materialModels::viscoplasticFluid::viscoplasticFluid
(
    const dictionary& coeffs,
    const yieldViscosity::lawType law
)
:
    materialModel(coeffs, true),
    viscosity_(coeffs, law),
    // rho and c within their ranges: rho c^2 and its quarter are finite
    c_(readCoeff("c", soundSpeedRange)),
    gamma_(readCoeffOrDefault("gamma", 7, exponentRange)),
    wholeGamma_
    (
        gamma_ == std::round(gamma_) && gamma_ >= 1 && gamma_ <= 16
      ? int(gamma_)
      : 0
    ),
    pMin_(readCoeffOrDefault("pMin", 0, pressureCutRange)),
    G_
    (
        readCoeffOrDefault
        (
            "shearModulus",
            law == yieldViscosity::lawType::Newtonian ? 0 : 0.25*rho_*c_*c_,
            stressRange
        )
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::materialModels::viscoplasticFluid::waveSpeed() const
{
    return c_*std::sqrt(1 + 4*G_/(3*rho_*c_*c_));
}


Foam::scalar
Foam::materialModels::viscoplasticFluid::explicitViscosity() const
{
    return G_ > 0 ? 0 : viscosity_.maxViscosity();
}


Foam::scalar Foam::materialModels::viscoplasticFluid::restJ
(
    const scalar p
) const
{
    return std::pow(1 + gamma_*p/(rho_*c_*c_), -1/gamma_);
}


void Foam::materialModels::viscoplasticFluid::updateStress
(
    particleArrays&,
    const materialParticles& mp,
    const scalar dt
) const
{
    typedef materialParticles::tensor3 tensor3;
    const double G = G_;

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < mp.n; ++i)
    {
        const tensor3 l = mp.gradU(i);
        const tensor3 D = materialParticles::dev(mp.strainRate(i, l));
        const double gammaDot = std::sqrt(2*D.squaredNorm());
        const double mu = viscosity_(gammaDot);

        tensor3 s = 2*mu*D;
        if (G > 0 && mu > 0)
        {
            // Maxwell relaxation towards 2 mu D, exact over the step
            const tensor3 s0 = materialParticles::dev
            (
                materialParticles::rotate(mp.stress(i), l, dt)
            );
            s += (s0 - s)*std::exp(-G*dt/mu);
        }
        s.diagonal().array() -= pressure(mp.J[i]);
        mp.setStress(i, s);
    }
}


void Foam::materialModels::viscoplasticFluid::describe(Ostream& os) const
{
    os  << type() << " fluid (rho = " << rho_ << " kg/m^3, Tait c = " << c_
        << " m/s, gamma = " << gamma_ << ", pMin = " << pMin_ << " Pa, ";
    viscosity_.describe(os);
    if (G_ > 0)
    {
        os  << ", Maxwell G = " << G_ << " Pa";
    }
    os  << ", volumetric smoothing " << (volumetricSmoothing_ ? "on" : "off")
        << ")";
}


// ************************************************************************* //
