/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "bedFrictionModel.H"
#include "knownKeywords.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(bedFrictionModel, 0);
    defineRunTimeSelectionTable(bedFrictionModel, dictionary);
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::scalar Foam::bedFrictionModel::readFrictionAngle() const
{
    knownKeywords::add(coeffs_, {"phi"});
    const scalar phi = coeffs_.get<scalar>("phi");
    if (!(phi >= 0 && phi < 90))
    {
        FatalIOErrorInFunction(coeffs_)
            << "phi = " << phi << " is invalid; allowed: 0 <= phi < 90"
            << " (friction angle in degrees)" << exit(FatalIOError);
    }
    return phi;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bedFrictionModel::bedFrictionModel(const dictionary& coeffs)
:
    coeffs_(coeffs)
{}


// ************************************************************************* //
