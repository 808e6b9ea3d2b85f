/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "linearShape.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace shapeFunctions
{
    defineTypeNameAndDebug(linearShape, 0);
    addToRunTimeSelectionTable(shapeFunction, linearShape, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::shapeFunctions::linearShape::linearShape
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
