/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "fpTrapsHeld.H"
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fpTrapsHeld::fpTrapsHeld()
{
    std::feholdexcept(&env_);
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::fpTrapsHeld::~fpTrapsHeld()
{
    // A flag left raised would trap at the next operation once the traps
    // are back (x87)
    std::feclearexcept(FE_ALL_EXCEPT);
    std::fesetenv(&env_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::fpTrapsHeld::readFinite(const std::string& text, scalar& value)
{
    const fpTrapsHeld hold;
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    const double parsed = std::strtod(begin, &end);
    if (end == begin)
    {
        return false;
    }
    while (std::isspace(static_cast<unsigned char>(*end)))
    {
        ++end;
    }
    if (*end != '\0' || !std::isfinite(parsed))
    {
        return false;
    }
    value = parsed;
    return true;
}


// ************************************************************************* //
