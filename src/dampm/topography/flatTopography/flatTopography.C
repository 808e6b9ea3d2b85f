/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "flatTopography.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"
#include "IOmanip.H"
#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace topographyModels
{
    defineTypeNameAndDebug(flatTopography, 0);
    addToRunTimeSelectionTable(topographyModel, flatTopography, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::topographyModels::flatTopography::flatTopography
(
    const dictionary& coeffs,
    const fileName& caseDir
)
:
    topographyModel(coeffs, caseDir),
    Z0_(coeffs.getOrDefault<scalar>("Z0", 0))
{
    knownKeywords::add(coeffs, {"Z0"});
    if (!(std::abs(Z0_) <= maxAbsZ))
    {
        FatalIOErrorInFunction(coeffs)
            << setprecision(12)
            << "Z0 = " << Z0_ << " is invalid; allowed: |Z0| <= " << maxAbsZ
            << " m" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::topographyModels::flatTopography::Z
(
    const scalar x,
    const scalar y
) const
{
    return Z0_;
}


void Foam::topographyModels::flatTopography::describe(Ostream& os) const
{
    os  << "flat (Z0 = " << Z0_ << " m)";
}


// ************************************************************************* //
