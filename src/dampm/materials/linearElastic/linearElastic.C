/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "linearElastic.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace materialModels
{
    defineTypeNameAndDebug(linearElastic, 0);
    addToRunTimeSelectionTable(materialModel, linearElastic, dictionary);
}
}


const Foam::materialModel::coeffRange
Foam::materialModels::linearElastic::youngsModulusRange
{
    0, false, 1e13, true, "Pa"
};


const Foam::materialModel::coeffRange
Foam::materialModels::linearElastic::poissonRange
{
    0, true, 0.5, false, ""
};


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::materialModels::linearElastic::linearElastic(const dictionary& coeffs)
:
    materialModel(coeffs, false),
    // Both checked before the moduli: nu = 0.5 divides by zero in K
    E_(readCoeff("E", youngsModulusRange)),
    nu_(readCoeff("nu", poissonRange)),
    G_(E_/(2*(1 + nu_))),
    K_(E_/(3*(1 - 2*nu_)))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::materialModels::linearElastic::waveSpeed() const
{
    return std::sqrt((K_ + 4*G_/3)/rho_);
}


Foam::scalar Foam::materialModels::linearElastic::restJ(const scalar p) const
{
    return std::exp(-p/K_);
}


void Foam::materialModels::linearElastic::updateStress
(
    particleArrays&,
    const materialParticles& mp,
    const scalar dt
) const
{
    #pragma omp parallel for schedule(static)
    for (label i = 0; i < mp.n; ++i)
    {
        mp.setStress(i, trialStress(mp, i, dt));
    }
}


void Foam::materialModels::linearElastic::describe(Ostream& os) const
{
    os  << "linearElastic (rho = " << rho_ << " kg/m^3, E = " << E_
        << " Pa, nu = " << nu_ << ", volumetric smoothing "
        << (volumetricSmoothing_ ? "on" : "off") << ")";
}


// ************************************************************************* //
