/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "GIMPShape.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace shapeFunctions
{
    defineTypeNameAndDebug(GIMPShape, 0);
    addToRunTimeSelectionTable(shapeFunction, GIMPShape, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::shapeFunctions::GIMPShape::GIMPShape
(
    const dictionary& coeffs,
    const scalar particleHalfWidth
)
:
    shapeFunction(coeffs),
    lp_(coeffs.getOrDefault<scalar>("particleHalfWidth", particleHalfWidth))
{
    knownKeywords::add(coeffs, {"particleHalfWidth"});

    if (!(lp_ > 0 && lp_ <= 0.5))
    {
        FatalIOErrorInFunction(coeffs)
            << "particleHalfWidth = " << lp_ << " is invalid; allowed:"
            << " 0 < particleHalfWidth <= 0.5 (cells)" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::shapeFunctions::GIMPShape::describe(Ostream& os) const
{
    os  << type() << " (particle half-width " << lp_ << " cells)";
}


// ************************************************************************* //
