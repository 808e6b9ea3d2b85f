/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "speedLimit.H"
#include "knownKeywords.H"
#include "mpmTime.H"
#include "OStringStream.H"

#include <cmath>
#include <cstdio>
#include <cstdlib>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::speedLimit::factor = 10;

const Foam::scalar Foam::speedLimit::maximum = 1e5;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::speedLimit::speedLimit(const dictionary& dict)
:
    limit_(dict.getOrDefault<scalar>("speedLimit", 0)),
    given_(dict.found("speedLimit"))
{
    knownKeywords::add(dict, {"speedLimit"});
    if (given_ && !(limit_ > 0 && limit_ <= maximum))
    {
        FatalIOErrorInFunction(dict)
            << "speedLimit = " << limit_ << " is invalid; allowed:"
            << " 0 < speedLimit <= " << maximum << " [m/s]"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::speedLimit::threeDigits(const scalar x)
{
    char digits[32];
    std::snprintf(digits, sizeof(digits), "%.3g", x);
    return std::strtod(digits, nullptr);
}


void Foam::speedLimit::setDefault(const scalar speedScale)
{
    if (!given_)
    {
        limit_ = min(threeDigits(factor*speedScale), maximum);
    }
}


void Foam::speedLimit::writeState(dictionary& state) const
{
    state.set("speedLimit", limit_);
}


void Foam::speedLimit::readState(const dictionary& state)
{
    if (!given_)
    {
        limit_ = state.get<scalar>("speedLimit");
    }
}


void Foam::speedLimit::blownUp
(
    const std::string& what,
    const std::string& why,
    const mpmTime& runTime
)
{
    const word& last = runTime.lastComplete();
    FatalErrorInFunction
        << what.c_str() << " at time " << runTime.timeName() << " (deltaT "
        << runTime.deltaTValue() << " s)" << why.c_str() << ": the state is"
        << " taken as blown up; nothing written for it. Last good time"
        << " directory: " << (last.empty() ? word("none") : last)
        << exit(FatalError);
}


void Foam::speedLimit::check
(
    const scalar speed,
    const char* what,
    const mpmTime& runTime
) const
{
    if (speed > limit_)
    {
        OStringStream found, why;
        found<< what << ' ' << speed << " m/s";
        why << " exceeds speedLimit " << limit_ << " m/s ("
            << (given_ ? "given" : "default: ") ;
        if (!given_)
        {
            why << factor << " x the speed scale of the start";
        }
        why << ')';
        blownUp(found.str(), why.str(), runTime);
    }
}


void Foam::speedLimit::describe(Ostream& os) const
{
    os  << limit_ << " m/s (the run stops above it"
        << (given_ ? ")" : ", default)");
}


// ************************************************************************* //
