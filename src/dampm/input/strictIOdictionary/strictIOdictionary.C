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
#include "IFstream.H"
#include "HashSet.H"

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

void Foam::strictIOdictionary::skipValue(Istream& is)
{
    // Up to the ';' outside brackets and blocks; a block ends the entry
    // (a #codeStream { ... }, a keyword's dictionary)
    label depth = 0;
    token t;
    while (is.read(t).good() || t.good())
    {
        if
        (
            t == token::BEGIN_LIST
         || t == token::BEGIN_BLOCK
        )
        {
            ++depth;
        }
        else if (t == token::END_LIST)
        {
            --depth;
        }
        else if (t == token::END_BLOCK)
        {
            if (--depth <= 0)
            {
                return;
            }
        }
        else if (t == token::END_STATEMENT && depth <= 0)
        {
            return;
        }
        if (is.eof())
        {
            return;
        }
    }
}


void Foam::strictIOdictionary::checkLiteral
(
    Istream& is,
    const fileName& dir,
    const string& scope,
    HashSet<string>& keys,
    bool& strict
)
{
    token t;
    while (is.read(t).good() || t.good())
    {
        if (t == token::END_BLOCK)
        {
            return;
        }
        if (!(t.isWord() || t.isString()) || t.isPunctuation())
        {
            if (is.eof())
            {
                return;
            }
            continue;
        }
        const string key(t.isWord() ? t.wordToken() : t.stringToken());
        if (key.starts_with("#include") || key == "#sinclude")
        {
            // The included file's entries belong to this scope
            token file;
            is.read(file);
            fileName name(file.isString() ? file.stringToken() : string());
            name.expand();
            if (!name.isAbsolute())
            {
                name = dir/name;
            }
            if (isFile(name))
            {
                IFstream included(name);
                checkLiteral(included, name.path(), scope, keys, strict);
            }
            continue;
        }
        if (key == "#inputMode")
        {
            token mode;
            is.read(mode);
            strict = mode.isWord() && mode.wordToken() == "error";
            continue;
        }
        if (key.starts_with("#") || key.starts_with("$"))
        {
            // #overwrite, #remove, ...: a replacement on purpose; $name: an
            // inherited entry, which the keywords after it may override
            skipValue(is);
            continue;
        }
        if (strict && keys.found(key))
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, is.name(), is.lineNumber()
            )   << "duplicate keyword \"" << key.c_str() << "\" in "
                << (scope.empty() ? string("the top level") : scope).c_str()
                << " of "
                << is.name() << ": each keyword may appear once in a"
                << " dictionary (a second barrier or region of the same name"
                << " would replace or merge into the first); allowed: distinct"
                << " names, entries inherited with $name overridden, or, to"
                << " replace an entry on purpose, #overwrite " << key.c_str()
                << " ...;" << exit(FatalIOError);
        }
        keys.insert(key);
        token next;
        is.read(next);
        if (next == token::BEGIN_BLOCK)
        {
            HashSet<string> sub;
            checkLiteral
            (
                is, dir, scope.empty() ? key : string(scope + '.' + key), sub,
                strict
            );
        }
        else if (!(next == token::END_STATEMENT))
        {
            is.putBack(next);
            skipValue(is);
        }
    }
}


void Foam::strictIOdictionary::read(Istream& is, dictionary& dict)
{
    dict.clear();
    dict.name() = is.name();
    {
        const fpTrapsHeld hold;
        dict.read(is);
    }

    // The keywords as written (not as merged): a $name's entries may be
    // overridden, a keyword written twice in one scope may not
    is.rewind();
    HashSet<string> keys;
    bool strict = true;
    checkLiteral(is, fileName(is.name()).path(), string(), keys, strict);
}


bool Foam::strictIOdictionary::readData(Istream& is)
{
    read(is, *this);
    return !is.bad();
}


// ************************************************************************* //
