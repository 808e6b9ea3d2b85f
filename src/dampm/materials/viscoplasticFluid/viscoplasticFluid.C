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
#include "vectorLanes.H"
#include <type_traits>

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


Foam::scalar Foam::materialModels::viscoplasticFluid::maxJ
(
    const scalar dt,
    const scalar h,
    const scalar a
) const
{
    // Alone on its nodes a particle's affine modes are free: the stiffest
    // is deviatoric, modulus 2G (the pressure is cut beyond J = 1) or the
    // viscous 2 mu, on the mass density rho/J, times a/h^2 (6/h^2 for the
    // quadratic B-spline). Explicit steps keep an oscillation stable while
    // w dt <= 2, w^2 = (J/rho) 2G a/h^2, and a decay while its rate
    // (J/rho) 2 mu a/h^2 is at most 2/dt. (Below 1 no J would do: the step
    // itself is too long for a lone particle.)
    scalar J = VGREAT;
    if (G_ > 0)
    {
        J = 2*rho_*h*h/(G_*a*dt*dt);
    }
    else if (viscosity_.maxViscosity() > 0)
    {
        J = rho_*h*h/(viscosity_.maxViscosity()*a*dt);
    }
    return max(J, 1.0);
}


template<bool Maxwell>
Foam::label Foam::materialModels::viscoplasticFluid::updateBlock
(
    const materialParticles& mp,
    const label first,
    const label n,
    const scalar dt
) const
{
    const double* const* L = mp.L;
    double* const* sigma = mp.sigma;

    // Deviatoric strain rate, symmetric: xx xy xz yy yz zz. The trace
    // (div with volumetric smoothing) drops out of the deviator, so it is
    // taken from L itself
    alignas(64) double D[6][blockSize];
    alignas(64) double gammaDot[blockSize];
    #pragma omp simd
    for (label k = 0; k < n; ++k)
    {
        const label i = first + k;
        const double mean = (L[0][i] + L[4][i] + L[8][i])/3;
        D[0][k] = L[0][i] - mean;
        D[1][k] = 0.5*(L[1][i] + L[3][i]);
        D[2][k] = 0.5*(L[2][i] + L[6][i]);
        D[3][k] = L[4][i] - mean;
        D[4][k] = 0.5*(L[5][i] + L[7][i]);
        D[5][k] = L[8][i] - mean;
        const double normSqr =
            D[0][k]*D[0][k] + D[3][k]*D[3][k] + D[5][k]*D[5][k]
          + 2*(D[1][k]*D[1][k] + D[2][k]*D[2][k] + D[4][k]*D[4][k]);
        gammaDot[k] = std::sqrt(2*normSqr);
    }

    // Per particle, in scalar code, since the viscosity law and the Tait
    // power branch and call expm1, pow and exp: the viscosity, the Maxwell
    // element's decay over the step (0: no stress memory) and the pressure
    alignas(64) double twoMu[blockSize];
    alignas(64) double decay[blockSize];
    alignas(64) double pressureOf[blockSize];
    label nInverted = 0;
    for (label k = 0; k < n; ++k)
    {
        const double mu = viscosity_(gammaDot[k]);
        twoMu[k] = 2*mu;
        decay[k] = Maxwell && mu > 0 ? std::exp(-G_*dt/mu) : 0;
        // (A J not above minJ, or not a number: its pressure would divide
        // by zero; the caller stops the run)
        const double J = mp.J[first + k];
        const bool valid = J > minJ;
        nInverted += !valid;
        pressureOf[k] = valid ? pressure(J) : 0;
    }

    // The stress: 2 mu D, with a Maxwell element relaxed towards it from
    // the last deviatoric stress rotated over the step (Jaumann:
    // s + dt (W s - s W), W the spin), then the pressure. W s - s W =
    // A + A^T with A = W s, written out for the symmetric s and the spin's
    // three components; its trace is zero, so the rotated stress's deviator
    // is the deviator of s plus it. Written once for a Real: four
    // particles a lanes4 (the same operations lane by lane), the rest one
    // at a time. (A loop for the vectoriser would stay scalar: under
    // trapping math it does not compute the relaxed stress of a particle
    // that keeps the viscous one.)
    const auto stress = [&](const label k, const auto zero)
    {
        typedef std::remove_const_t<decltype(zero)> Real;
        const label i = first + k;
        const Real mu2 = loadAt<Real>(twoMu, k);
        Real s[6];
        for (int m = 0; m < 6; ++m)
        {
            s[m] = mu2*loadAt<Real>(D[m], k);
        }
        if (Maxwell)
        {
            const auto Lc = [&](const int c) { return loadAt<Real>(L[c], i); };
            const Real wxy = 0.5*(Lc(1) - Lc(3));
            const Real wxz = 0.5*(Lc(2) - Lc(6));
            const Real wyz = 0.5*(Lc(5) - Lc(7));
            const Real sxx = loadAt<Real>(sigma[0], i);
            const Real sxy = loadAt<Real>(sigma[1], i);
            const Real sxz = loadAt<Real>(sigma[2], i);
            const Real syy = loadAt<Real>(sigma[3], i);
            const Real syz = loadAt<Real>(sigma[4], i);
            const Real szz = loadAt<Real>(sigma[5], i);
            const Real mean = (sxx + syy + szz)/3;
            const Real s0[6] =
            {
                sxx - mean + dt*2*(wxy*sxy + wxz*sxz),
                sxy + dt*(wxy*(syy - sxx) + wxz*syz + wyz*sxz),
                sxz + dt*(wxz*(szz - sxx) + wxy*syz - wyz*sxy),
                syy - mean + dt*2*(wyz*syz - wxy*sxy),
                syz + dt*(wyz*(szz - syy) - wxy*sxz - wxz*sxy),
                szz - mean - dt*2*(wxz*sxz + wyz*syz)
            };
            // No decay (mu = 0, or exp underflowing): the viscous stress,
            // as s + (s0 - s) 0 gives for a finite s0. Both are computed,
            // and there the relaxation from s itself (0 for a finite s),
            // so that no s0, however large, can trap where it is not used
            const Real dk = loadAt<Real>(decay, k);
            const auto relaxes = dk > 0.0;
            for (int m = 0; m < 6; ++m)
            {
                const Real from = select(relaxes, s0[m], s[m]);
                s[m] = select(relaxes, s[m] + (from - s[m])*dk, s[m]);
            }
        }
        const Real pk = loadAt<Real>(pressureOf, k);
        s[0] -= pk;
        s[3] -= pk;
        s[5] -= pk;
        for (int m = 0; m < 6; ++m)
        {
            storeAt(sigma[m], i, s[m]);
        }
        storeAt(mp.p, i, -(s[0] + s[3] + s[5])/3);
    };
    label k = 0;
    for (; k + 4 <= n; k += 4)
    {
        stress(k, lanes4{});
    }
    for (; k < n; ++k)
    {
        stress(k, 0.0);
    }
    return nInverted;
}


void Foam::materialModels::viscoplasticFluid::inverted
(
    const particleArrays& particles,
    const materialParticles& mp
) const
{
    label i = 0;
    while (i < mp.n - 1 && mp.J[i] > minJ)
    {
        ++i;
    }
    const double* x[3];
    for (int d = 0; d < 3; ++d)
    {
        x[d] = particles.component(particleArrays::X + d);
    }
    FatalErrorInFunction
        << "particle " << i << " at (" << x[0][i] << " " << x[1][i] << " "
        << x[2][i] << ") has the volume ratio J = " << mp.J[i]
        << " after one step: its volume went through zero, which no"
        << " material survives. The step is too long for the flow there;"
        << " lower maxCo in system/controlDict (the stable step of a"
        << " weakly compressible fluid is about 0.4 of a cell over the wave"
        << " speed). Nothing is written for this step: restart from the"
        << " latest time directory written completely" << exit(FatalError);
    std::abort();  // (not reached)
}


void Foam::materialModels::viscoplasticFluid::updateStress
(
    particleArrays& particles,
    const materialParticles& mp,
    const scalar dt
) const
{
    const label nBlocks = (mp.n + blockSize - 1)/blockSize;

    label nInverted = 0;
    #pragma omp parallel for schedule(static) reduction(+:nInverted)
    for (label blocki = 0; blocki < nBlocks; ++blocki)
    {
        const label first = blocki*blockSize;
        const label n = min(label(blockSize), mp.n - first);
        nInverted +=
            G_ > 0
          ? updateBlock<true>(mp, first, n, dt)
          : updateBlock<false>(mp, first, n, dt);
    }
    if (nInverted)
    {
        inverted(particles, mp);
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
