/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "materialModel.H"
#include "knownKeywords.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(materialModel, 0);
    defineRunTimeSelectionTable(materialModel, dictionary);
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::scalar Foam::materialModel::readCoeff
(
    const word& key,
    const bool positive
) const
{
    knownKeywords::add(coeffs_, {key});
    const scalar value = coeffs_.get<scalar>(key);
    if (positive ? !(value > 0) : !(value >= 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << key << " = " << value << " is invalid; allowed: " << key
            << (positive ? " > 0" : " >= 0") << exit(FatalIOError);
    }
    return value;
}


Foam::scalar Foam::materialModel::readCoeffOrDefault
(
    const word& key,
    const scalar deflt
) const
{
    knownKeywords::add(coeffs_, {key});
    return coeffs_.found(key) ? readCoeff(key, false) : deflt;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::materialModel::materialModel
(
    const dictionary& coeffs,
    const bool smoothByDefault
)
:
    coeffs_(coeffs),
    rho_(readCoeff("rho")),
    volumetricSmoothing_
    (
        coeffs.getOrDefault<bool>("volumetricSmoothing", smoothByDefault)
    )
{
    knownKeywords::add(coeffs, {"volumetricSmoothing"});
}


// ************************************************************************* //
