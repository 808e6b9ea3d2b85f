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
#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(materialModel, 0);
    defineRunTimeSelectionTable(materialModel, dictionary);
}


const Foam::materialModel::coeffRange Foam::materialModel::densityRange
{
    1e-3, true, 1e5, true, "kg/m^3"
};

const Foam::materialModel::coeffRange Foam::materialModel::stressRange
{
    0, true, 1e13, true, "Pa"
};


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

void Foam::materialModel::checkCoeff
(
    const word& key,
    const scalar value,
    const coeffRange& range
) const
{
    // Finite first: a comparison with NaN would raise a signal
    const bool ok =
        std::isfinite(value)
     && (range.loIncluded ? value >= range.lo : value > range.lo)
     && (range.hiIncluded ? value <= range.hi : value < range.hi);
    if (!ok)
    {
        FatalIOErrorInFunction(coeffs_)
            << key << " = " << value << " is invalid; allowed: " << range.lo
            << (range.loIncluded ? " <= " : " < ") << key
            << (range.hiIncluded ? " <= " : " < ") << range.hi
            << (*range.unit ? " [" : "") << range.unit
            << (*range.unit ? "]" : "") << exit(FatalIOError);
    }
}


Foam::scalar Foam::materialModel::readCoeff
(
    const word& key,
    const coeffRange& range
) const
{
    knownKeywords::add(coeffs_, {key});
    const scalar value = coeffs_.get<scalar>(key);
    checkCoeff(key, value, range);
    return value;
}


Foam::scalar Foam::materialModel::readCoeffOrDefault
(
    const word& key,
    const scalar deflt,
    const coeffRange& range
) const
{
    if (coeffs_.found(key))
    {
        return readCoeff(key, range);
    }
    knownKeywords::add(coeffs_, {key});
    return deflt;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::materialModel::materialModel
(
    const dictionary& coeffs,
    const bool smoothByDefault
)
:
    coeffs_(coeffs),
    rho_(readCoeff("rho", densityRange)),
    volumetricSmoothing_
    (
        coeffs.getOrDefault<bool>("volumetricSmoothing", smoothByDefault)
    )
{
    knownKeywords::add(coeffs, {"volumetricSmoothing"});
}


// ************************************************************************* //
