/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "rheologyModel.H"
#include "knownKeywords.H"
#include "boundedScalar.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(rheologyModel, 0);
    defineRunTimeSelectionTable(rheologyModel, dictionary);
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::scalar Foam::rheologyModel::readNonNegative(const word& key) const
{
    knownKeywords::add(coeffs_, {key});
    return boundedScalar
    (
        coeffs_, key, coeffs_.get<scalar>(key), scalarBound::nonNegative
    );
}


void Foam::rheologyModel::describeStress(Ostream& os) const
{
    if (G_ > 0)
    {
        os  << "Maxwell stress, G = " << G_ << " Pa";
    }
    else if (defaultModulus_)
    {
        os  << "Maxwell stress, G not set";
    }
    else
    {
        os  << "viscous stress";
    }
}


void Foam::rheologyModel::readShearModulus(const bool defaultMaxwell)
{
    knownKeywords::add(coeffs_, {"shearModulus"});
    if (coeffs_.found("shearModulus"))
    {
        G_ = readNonNegative("shearModulus");
        defaultModulus_ = false;
    }
    else
    {
        G_ = 0;
        defaultModulus_ = defaultMaxwell;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rheologyModel::rheologyModel(const dictionary& coeffs)
:
    coeffs_(coeffs),
    G_(0),
    defaultModulus_(false)
{}


// ************************************************************************* //
