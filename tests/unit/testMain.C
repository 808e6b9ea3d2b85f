/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    GoogleTest main for dampm: OpenFOAM's fatal errors throw Foam::error so
    that tests can assert that bad input is refused, and what it says.
    Each test starts at the write precision of a fresh process: a Time sets
    the default and the global streams' (the fatal errors' messages too)
    from its controlDict's writePrecision, and a message's numbers would
    otherwise depend on which tests ran before it in the same process
    (CTest runs each alone).

\*---------------------------------------------------------------------------*/

#include "error.H"
#include "IOstreams.H"
#include <gtest/gtest.h>

namespace
{

//- Restores the write precisions a Time sets (Time::readDict) before
//  every test
class startingPrecision
:
    public ::testing::EmptyTestEventListener
{
    const unsigned precision_ = Foam::IOstream::defaultPrecision();

    void OnTestStart(const ::testing::TestInfo&) override
    {
        using namespace Foam;
        IOstream::defaultPrecision(precision_);
        OSstream* const streams[] = {&Sout, &Serr, &Pout, &Perr};
        for (OSstream* os : streams)
        {
            os->precision(precision_);
        }
        FatalError().precision(precision_);
        FatalIOError.error::operator()().precision(precision_);
    }
};

} // End anonymous namespace


int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    ::testing::UnitTest::GetInstance()->listeners().Append
    (
        new startingPrecision
    );
    Foam::FatalError.throwExceptions();
    Foam::FatalIOError.throwExceptions();
    return RUN_ALL_TESTS();
}


// ************************************************************************* //
