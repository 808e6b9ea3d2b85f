/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "structureInput.H"
#include "knownKeywords.H"
#include "boundedScalar.H"
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
    return boundedScalar
    (
        dict, keyword, dict.get<scalar>(keyword), scalarBound::positive, units
    );
}


Foam::scalar Foam::structureInput::nonNegative
(
    const dictionary& dict,
    const word& keyword,
    const scalar deflt,
    const char* units
)
{
    return boundedScalar
    (
        dict, keyword, dict.getOrDefault<scalar>(keyword, deflt),
        scalarBound::nonNegative, units
    );
}


void Foam::structureInput::onlyKeywords
(
    const dictionary& dict,
    const wordList& allowed
)
{
    // Checked here: the suite's unread-keyword warnings need not look
    knownKeywords::add(dict, allowed);
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


void Foam::structureInput::checkSize
(
    const dictionary& dict,
    const word& keyword,
    const label size,
    const label expected,
    const char* what
)
{
    if (size != expected)
    {
        FatalIOErrorInFunction(dict)
            << "Entry " << keyword << " of " << dict.name() << " has "
            << size << " values; expected " << expected << ", " << what
            << " of the structure built from its dictionary"
            << exit(FatalIOError);
    }
}


// ************************************************************************* //
