/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "boundedScalar.H"
#include <cmath>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::boundedScalar
(
    const dictionary& dict,
    const word& keyword,
    const scalar value,
    const scalarBound bound,
    const char* units
)
{
    const bool positive = bound == scalarBound::positive;
    if (!((positive ? value > 0 : value >= 0) && std::isfinite(value)))
    {
        FatalIOErrorInFunction(dict)
            << keyword << " = " << value << " is invalid; allowed: "
            << keyword << (positive ? " > 0" : " >= 0")
            << (*units ? " " : "") << units << exit(FatalIOError);
    }
    return value;
}


// ************************************************************************* //
