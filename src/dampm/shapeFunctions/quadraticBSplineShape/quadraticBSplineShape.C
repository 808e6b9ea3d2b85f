/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "quadraticBSplineShape.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace shapeFunctions
{
    defineTypeNameAndDebug(quadraticBSplineShape, 0);
    addToRunTimeSelectionTable
    (
        shapeFunction,
        quadraticBSplineShape,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::shapeFunctions::quadraticBSplineShape::quadraticBSplineShape
(
    const dictionary& coeffs,
    const scalar
)
:
    shapeFunction(coeffs)
{
    knownKeywords::add(coeffs, {});
}


// ************************************************************************* //
