/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    A flexible structure as a whole: its stable time step and sub-cycling,
    the energy budget of a loaded, damped membrane with ropes, the same
    result on one and two threads, the STL and panel geometries, and bad
    input refused with the keyword named.

\*---------------------------------------------------------------------------*/

#include "scratchDir.H"
#include "structureTestTools.H"
#include "errorsThrown.H"
#include "OSspecific.H"
#include <gtest/gtest.h>
#include <fstream>
#include <cmath>
#ifdef _OPENMP
#include <omp.h>
#endif

using namespace Foam;
using namespace Foam::structureTest;

namespace
{

//- The FatalIOError message building a structure from text ("" if none)
std::string inputError(const std::string& text)
{
    try
    {
        const errorsThrown throwing;
        flexibleStructure s(dictionaryOf(text), ".");
    }
    catch (const IOerror& err)
    {
        return err.message();
    }
    return "";
}


//- Run the barrier under a uniform load normal to it for time t
flexibleStructure loadedBarrier(const std::string& damping, const scalar t)
{
    flexibleStructure s(dictionaryOf(barrier + ropes + damping), ".");
    loadBarrier(s);
    const scalar dtFlow = 1e-3;
    while (s.time() < t - 0.5*dtFlow)
    {
        s.subCycle(dtFlow);
    }
    return s;
}

} // End anonymous namespace


TEST(flexibleStructure, SubCycleTakesStableEqualStepsNamingTheLimiter)
{
    flexibleStructure s(dictionaryOf(barrier + ropes), ".");
    // The membrane: smallest altitude of a 0.25 x 0.25 right triangle over
    // sqrt((E/(1 - nu^2) + S0)/rho), times the default safety 0.5
    const double c = std::sqrt((2e9/0.91 + 1e5)/1000);
    EXPECT_NEAR(s.stableTimeStep(), 0.5*0.25/std::sqrt(2.0)/c, 1e-15);
    EXPECT_EQ(s.limiter().substr(0, 17), "membrane triangle");

    const scalar dtFlow = 10.5*s.stableTimeStep();
    const flexibleStructure::subCycleReport r = s.subCycle(dtFlow);
    EXPECT_EQ(r.nSteps, 11);
    EXPECT_NEAR(r.dt*r.nSteps, dtFlow, 1e-15);
    EXPECT_NEAR(s.time(), dtFlow, 1e-15);

    // Stiffness-proportional damping beta: the highest mode, omega =
    // 2/dt_e, damped by xi = beta omega/2 is stable up to
    // dt_e (sqrt(1 + xi^2) - xi)
    flexibleStructure damped
    (
        dictionaryOf
        (
            barrier + ropes + "damping { stiffnessProportional 1e-4; }"
        ),
        "."
    );
    const double dte = 0.25/std::sqrt(2.0)/c;
    const double xi = 1e-4/dte;
    EXPECT_NEAR
    (
        damped.stableTimeStep(),
        0.5*dte*(std::sqrt(1 + xi*xi) - xi),
        1e-15
    );

    // A stiff rope limits instead
    flexibleStructure stiff
    (
        dictionaryOf
        (
            barrier + "ropes { top { from (0 0 2); to (-1 -1 3); EA 1e11;"
            " linearDensity 5; segments 12; } }"
        ),
        "."
    );
    EXPECT_EQ(stiff.limiter().substr(0, 17), "rope top segment ");
    EXPECT_NEAR
    (
        stiff.stableTimeStep(),
        0.5*std::sqrt(3.0)/12*std::sqrt(5/1e11),
        1e-15
    );
}


TEST(flexibleStructure, LoadedBarrierSettlesWithClosedBudgetAndReactions)
{
    // Stiffness- and mass-proportional damping and the brakes dissipate;
    // 2 s: 40 decay times of the mass-proportional damping
    const flexibleStructure s = loadedBarrier
    (
        "damping { massProportional 20; stiffnessProportional 1e-5; }",
        2
    );
    const flexibleStructure::energyBudget& e = s.energies();
    std::cout
        << "    work " << e.externalWork << " J: kinetic " << e.kinetic
        << ", membrane " << e.membraneStrain << ", ropes " << e.ropeStrain
        << ", damping " << e.dampingDissipation << ", brakes "
        << e.brakeDissipation << "; deflection " << s.maxDeflection()
        << " m" << std::endl;

    EXPECT_LT(e.kinetic, 1e-9*e.externalWork);
    EXPECT_GT(e.dampingDissipation, 0.1*e.externalWork);
    EXPECT_GT(e.brakeDissipation, 0);
    EXPECT_GT(e.ropeStrain, 0);
    constexpr double tol = 1e-3;    // O(dt^2) of the leapfrog; the lagged
                                    // stiffness damping: O(dt)
    EXPECT_NEAR(e.total(), e.externalWork, tol*e.externalWork);

    // At rest the supports, the side anchors and the ropes' anchors,
    // carry the load: 2 kPa on 4 m x 2 m
    vector R(Zero);
    for (const word& name : s.anchors().names())
    {
        R += s.reaction(name);
    }
    EXPECT_NEAR(R.y(), -16e3, 1e-6*16e3);
    EXPECT_NEAR(R.x(), 0, 1e-6*16e3);
    EXPECT_NEAR(R.z(), 0, 1e-6*16e3);
    EXPECT_LT(s.reaction("retainingLeft").y(), 0);
    EXPECT_LT(s.reaction("retainingRight").y(), 0);
}


TEST(flexibleStructure, SameResultOnOneAndTwoThreads)
{
#ifdef _OPENMP
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    const flexibleStructure one = loadedBarrier("", 0.02);
    omp_set_num_threads(2);
    const flexibleStructure two = loadedBarrier("", 0.02);
    omp_set_num_threads(threads);
    EXPECT_TRUE(one.nodes().x == two.nodes().x);
    EXPECT_TRUE(one.nodes().y == two.nodes().y);
    EXPECT_TRUE(one.nodes().vz == two.nodes().vz);
#else
    GTEST_SKIP() << "built without OpenMP";
#endif
}


TEST(flexibleStructure, STLAndPanelGiveTheSameMembrane)
{
    // Two triangles of the unit square, as an ASCII STL
    const fileName dir(scratchDir("structureTest"));
    mkDir(dir);
    std::ofstream(dir/"square.stl")
        << "solid square\n"
        << "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
        << "vertex 1 1 0\nendloop\nendfacet\n"
        << "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 1 0\n"
        << "vertex 0 1 0\nendloop\nendfacet\n"
        << "endsolid square\n";
    const std::string material =
        "type membrane; thickness 0.01; E 1e6; nu 0.25; rho 500;";
    const flexibleStructure stl
    (
        dictionaryOf(material + "geometry { type STL; file \"square.stl\"; }"),
        dir
    );
    const flexibleStructure panel
    (
        dictionaryOf
        (
            material + "geometry { type panel;"
            " corners ((0 0 0) (1 0 0) (1 1 0) (0 1 0)); resolution (1 1); }"
        ),
        dir
    );
    ASSERT_EQ(stl.nodes().size(), 4);
    ASSERT_EQ(panel.nodes().size(), 4);
    double massStl = 0, massPanel = 0;
    for (label nodei = 0; nodei < 4; ++nodei)
    {
        massStl += stl.nodes().mass[nodei];
        massPanel += panel.nodes().mass[nodei];
    }
    EXPECT_NEAR(massStl, 500*0.01, 1e-12);
    EXPECT_NEAR(massPanel, 500*0.01, 1e-12);
    EXPECT_EQ(stl.stableTimeStep(), panel.stableTimeStep());
}


TEST(flexibleStructure, BadInputNamesTheKeyword)
{
    const std::string panel =
        "type membrane;"
        "geometry { type panel; corners ((0 0 0) (1 0 0) (1 1 0) (0 1 0));"
        "    resolution (2 2); }"
        "E 1e6; rho 500;";

    const std::string negativeThickness =
        inputError(panel + "thickness -0.01; nu 0.3;");
    EXPECT_NE(negativeThickness.find("thickness = -0.01"), std::string::npos)
        << negativeThickness;
    EXPECT_NE(negativeThickness.find("thickness > 0"), std::string::npos);

    const std::string incompressible =
        inputError(panel + "thickness 0.01; nu 0.5;");
    EXPECT_NE(incompressible.find("nu = 0.5"), std::string::npos)
        << incompressible;
    EXPECT_NE(incompressible.find("-1 < nu < 0.5"), std::string::npos);

    const std::string ropeKeyword = inputError
    (
        panel + "thickness 0.01; nu 0.3;"
        "ropes { top { from (0 1 0); to (1 1 0); EA 1e6; linearDensity 1;"
        " pretention 10; } }"
    );
    EXPECT_NE(ropeKeyword.find("pretention"), std::string::npos)
        << ropeKeyword;
    EXPECT_NE(ropeKeyword.find("pretension"), std::string::npos);

    const std::string brakeKeyword = inputError
    (
        "type ropes; ropes { top { from (0 1 0); to (1 1 0); EA 1e6;"
        " linearDensity 1; brake { threshold 10; maxElongaton 1; } } }"
    );
    EXPECT_NE(brakeKeyword.find("maxElongaton"), std::string::npos)
        << brakeKeyword;

    const std::string type = inputError("type net;");
    EXPECT_NE(type.find("membrane"), std::string::npos) << type;

    const std::string damping = inputError
    (
        panel + "thickness 0.01; nu 0.3; damping { massproportional 1; }"
    );
    EXPECT_NE(damping.find("massproportional"), std::string::npos)
        << damping;

    const std::string anchor = inputError
    (
        panel + "thickness 0.01; nu 0.3;"
        " anchors { a { type box; min (5 5 5); max (6 6 6); } }"
    );
    EXPECT_NE(anchor.find("selects no node"), std::string::npos) << anchor;
}
