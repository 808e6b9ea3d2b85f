/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "expressionTopography.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace topographyModels
{
    defineTypeNameAndDebug(expressionTopography, 0);
    addToRunTimeSelectionTable
    (
        topographyModel,
        expressionTopography,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::topographyModels::expressionTopography::expressionTopography
(
    const dictionary& coeffs,
    const fileName& caseDir
)
:
    topographyModel(coeffs, caseDir),
    Z_(coeffs, "Z", wordList({"x", "y"}))
{
    knownKeywords::add(coeffs, {"Z"});
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::topographyModels::expressionTopography::Z
(
    const scalar x,
    const scalar y
) const
{
    const scalar xy[2] = {x, y};
    return Z_.value(xy);
}


Foam::vector2D Foam::topographyModels::expressionTopography::gradient
(
    const scalar x,
    const scalar y
) const
{
    const scalar xy[2] = {x, y};
    vector2D grad;
    Z_.value(xy, 0, grad.x());
    Z_.value(xy, 1, grad.y());
    return grad;
}


Foam::scalar Foam::topographyModels::expressionTopography::highestOver
(
    const scalar x0,
    const scalar x1,
    const scalar y0,
    const scalar y1
) const
{
    const scalarMinMax xy[2] = {{x0, x1}, {y0, y1}};
    return Z_.bounds(xy).max();
}


void Foam::topographyModels::expressionTopography::describe(Ostream& os) const
{
    os  << "expression (Z = ";
    Z_.write(os);
    os  << ')';
}


// ************************************************************************* //
