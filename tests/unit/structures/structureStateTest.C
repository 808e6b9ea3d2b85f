/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    The restart state of a flexible structure: a loaded barrier whose
    brakes have slid, saved through a file and read into a structure built
    afresh, continues bit for bit as the uninterrupted run; a state that
    does not fit the structure is refused naming the file and the entry.

\*---------------------------------------------------------------------------*/

#include "scratchDir.H"
#include "structureTestTools.H"
#include "errorsThrown.H"
#include "exactPrecision.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"
#include <gtest/gtest.h>
#ifdef _OPENMP
#include <omp.h>
#endif

using namespace Foam;
using namespace Foam::structureTest;

namespace
{

//- One thread while it lives: the energies are sums over threads, whose
//  order OpenMP leaves open beyond two
class oneThread
{
#ifdef _OPENMP
    const int threads_ = omp_get_max_threads();

public:

    oneThread()
    {
        omp_set_num_threads(1);
    }

    ~oneThread()
    {
        omp_set_num_threads(threads_);
    }
#endif
};


//- The state written to file as the solvers write theirs, read back
dictionary throughFile(const dictionary& state, const word& name)
{
    const fileName dir(scratchDir("structureState"));
    mkDir(dir);
    {
        // A stream takes its precision when it opens
        const exactPrecision exact;
        OFstream os(dir/name);
        state.writeEntries(os);
    }
    IFstream is(dir/name);
    return dictionary(is);
}


//- The barrier, loaded, after nFlow flow steps of 1 ms
flexibleStructure runBarrier(const label nFlow)
{
    flexibleStructure s(dictionaryOf(barrier + ropes), ".");
    loadBarrier(s);
    for (label stepi = 0; stepi < nFlow; ++stepi)
    {
        s.subCycle(1e-3);
    }
    return s;
}

} // End anonymous namespace


TEST(structureState, RestartContinuesBitForBit)
{
    const oneThread one;
    flexibleStructure whole = runBarrier(100);
    // The state holds a slid brake
    const label brakeSeg = whole.ropes().segments(0).first;
    ASSERT_GT(whole.ropes().plasticElongation()[brakeSeg], 0);
    ASSERT_LT(whole.ropes().plasticElongation()[brakeSeg], 0.5);

    dictionary state;
    whole.writeState(state);
    const dictionary saved = throughFile(state, "barrier");

    flexibleStructure restarted(dictionaryOf(barrier + ropes), ".");
    restarted.readState(saved);
    for (label stepi = 0; stepi < 100; ++stepi)
    {
        whole.subCycle(1e-3);
        restarted.subCycle(1e-3);
    }
    // The brake kept sliding after the restart
    EXPECT_GT
    (
        whole.ropes().plasticElongation()[brakeSeg],
        saved.get<scalarList>("plasticElongation")[brakeSeg]
    );

    const structureNodes& a = whole.nodes();
    const structureNodes& b = restarted.nodes();
    EXPECT_TRUE(a.x == b.x && a.y == b.y && a.z == b.z);
    EXPECT_TRUE(a.vx == b.vx && a.vy == b.vy && a.vz == b.vz);
    EXPECT_TRUE(a.fx == b.fx && a.fy == b.fy && a.fz == b.fz);
    EXPECT_TRUE
    (
        whole.ropes().plasticElongation()
     == restarted.ropes().plasticElongation()
    );
    EXPECT_TRUE(whole.ropes().tension() == restarted.ropes().tension());
    EXPECT_EQ(whole.time(), restarted.time());

    const flexibleStructure::energyBudget& e = whole.energies();
    const flexibleStructure::energyBudget& f = restarted.energies();
    EXPECT_EQ(e.kinetic, f.kinetic);
    EXPECT_EQ(e.membraneStrain, f.membraneStrain);
    EXPECT_EQ(e.ropeStrain, f.ropeStrain);
    EXPECT_EQ(e.dampingDissipation, f.dampingDissipation);
    EXPECT_EQ(e.brakeDissipation, f.brakeDissipation);
    EXPECT_EQ(e.externalWork, f.externalWork);
    EXPECT_GT(e.brakeDissipation, 0);
}


TEST(structureState, StateOfAnotherStructureIsRefused)
{
    dictionary state;
    runBarrier(1).writeState(state);
    const dictionary saved = throughFile(state, "fine");

    // The same barrier, coarser: fewer nodes than the state holds
    std::string coarse(barrier);
    coarse.replace(coarse.find("(16 8)"), 6, "(8 4)");
    flexibleStructure s(dictionaryOf(coarse + ropes), ".");

    std::string message;
    fileName file;
    try
    {
        const errorsThrown throwing;
        s.readState(saved);
    }
    catch (const IOerror& err)
    {
        message = err.message();
        file = err.ioFileName();
    }
    const label nFine = runBarrier(0).nodes().size();
    EXPECT_EQ(file.name(), "fine") << file;
    EXPECT_NE(message.find("positions"), std::string::npos) << message;
    EXPECT_NE
    (
        message.find
        (
            "has " + std::to_string(nFine) + " values; expected "
          + std::to_string(s.nodes().size()) + ", one per node"
        ),
        std::string::npos
    ) << message;
}


// ************************************************************************* //
