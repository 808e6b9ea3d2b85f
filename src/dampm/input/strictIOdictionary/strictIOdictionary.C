/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "strictIOdictionary.H"
#include "fpTrapsHeld.H"
#include "stringOps.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- The IOobject, not read yet: IOdictionary's constructor would read it
//  with its own readData (the virtual call of a base constructor), which
//  resets the input mode to merge
Foam::IOobject unread(const Foam::IOobject& io)
{
    Foam::IOobject copy(io);
    copy.readOpt() = Foam::IOobject::NO_READ;
    return copy;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::strictIOdictionary::strictIOdictionary(const IOobject& io)
:
    IOdictionary(unread(io))
{
    readOpt() = io.readOpt();
    readHeaderOk(IOstream::ASCII, IOdictionary::typeName);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::strictIOdictionary::read(Istream& is, dictionary& dict)
{
    dict.clear();
    dict.name() = is.name();

    // OpenFOAM's message for a duplicate is "duplicate entry: <keyword>" with
    // the file and line: caught here to say what is allowed
    string why;
    fileName file;
    label line = -1;
    const bool throwing = FatalIOError.throwExceptions();
    entry::globalInputMode = entry::inputMode::ERROR;
    try
    {
        const fpTrapsHeld hold;
        dict.read(is);
    }
    catch (const IOerror& err)
    {
        why = err.message();
        file = err.ioFileName();
        line = err.ioStartLineNumber();
    }
    entry::resetInputMode();
    FatalIOError.throwExceptions(throwing);

    if (why.empty())
    {
        return;
    }
    const string duplicate("duplicate entry: ");
    if (why.starts_with(duplicate))
    {
        const string key(stringOps::trim(why.substr(duplicate.size())));
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__, file, line
        )   << "duplicate keyword " << key << " in " << dict.name()
            << ": each keyword may appear once in a dictionary (a second"
            << " barrier or region of the same name would replace or merge"
            << " into the first); allowed: distinct names, or, to replace an"
            << " entry on purpose, #overwrite " << key << " ...;"
            << exit(FatalIOError);
    }
    FatalIOError
    (
        FUNCTION_NAME, __FILE__, __LINE__, file, line
    )   << why.c_str() << exit(FatalIOError);
}


bool Foam::strictIOdictionary::readData(Istream& is)
{
    read(is, *this);
    return !is.bad();
}


// ************************************************************************* //
