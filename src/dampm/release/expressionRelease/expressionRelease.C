/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "expressionRelease.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"
#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace releaseModels
{
    defineTypeNameAndDebug(expressionRelease, 0);
    addToRunTimeSelectionTable(releaseModel, expressionRelease, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::releaseModels::expressionRelease::expressionRelease
(
    const dictionary& dict,
    const topographyModel& topography,
    const fileName& caseDir
)
:
    releaseModel(dict, topography, caseDir),
    height_(dict, "height", wordList({"x", "y", "Z"}))
{
    knownKeywords::add(dict, {"height"});
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::releaseModels::expressionRelease::height
(
    const scalar x,
    const scalar y
) const
{
    // Negative is no release; NaN and inf are passed on to be refused, not
    // clamped (max(NaN, 0) would be 0)
    const scalar vars[3] = {x, y, topography_.Z(x, y)};
    const scalar h = height_.value(vars);
    return std::isfinite(h) ? max(h, scalar(0)) : h;
}


void Foam::releaseModels::expressionRelease::describe(Ostream& os) const
{
    os  << "expression (height = ";
    height_.write(os);
    os  << ", U = " << U_ << ')';
}


// ************************************************************************* //
