/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "structureInput.H"
#include "FlatOutput.H"
#include <cmath>

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::scalar Foam::structureInput::positive
(
    const dictionary& dict,
    const word& keyword,
    const char* units
)
{
    const scalar value = dict.get<scalar>(keyword);
    if (!(value > 0 && std::isfinite(value)))
    {
        FatalIOErrorInFunction(dict)
            << keyword << " = " << value << " is invalid; allowed: "
            << keyword << " > 0 " << units << exit(FatalIOError);
    }
    return value;
}


Foam::scalar Foam::structureInput::nonNegative
(
    const dictionary& dict,
    const word& keyword,
    const scalar deflt,
    const char* units
)
{
    const scalar value = dict.getOrDefault<scalar>(keyword, deflt);
    if (!(value >= 0 && std::isfinite(value)))
    {
        FatalIOErrorInFunction(dict)
            << keyword << " = " << value << " is invalid; allowed: "
            << keyword << " >= 0 " << units << exit(FatalIOError);
    }
    return value;
}


void Foam::structureInput::onlyKeywords
(
    const dictionary& dict,
    const wordList& allowed
)
{
    for (const entry& e : dict)
    {
        if (!allowed.found(e.keyword()))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown keyword " << e.keyword() << " in "
                << dict.dictName() << "; allowed: "
                << flatOutput(allowed) << exit(FatalIOError);
        }
    }
}


// ************************************************************************* //
