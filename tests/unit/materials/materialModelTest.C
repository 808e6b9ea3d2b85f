/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    materialModel: every model's coefficients refused outside their ranges
    with the keyword and the range in the message, with the traps of
    FOAM_SIGFPE on (nu = 0.5 divided by zero, rho c^2 of c = 1e300
    overflowed: signals before); the ends of the ranges accepted with
    finite derived values (the P-wave speed against its closed form); a
    regularised yield stress whose largest viscosity overflows refused by
    New with the traps held.

\*---------------------------------------------------------------------------*/

#include "materialState.H"
#include <gtest/gtest.h>
#include <cfenv>
#include <cmath>

using namespace Foam;

namespace
{

//- The FOAM_SIGFPE traps for a test's lifetime
class foamTraps
{
    const int before_;

public:

    foamTraps()
    :
        before_(fegetexcept())
    {
        feenableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
    }

    ~foamTraps()
    {
        fedisableexcept(FE_ALL_EXCEPT);
        feenableexcept(before_);
    }
};


//- The message of the error New throws ("" if none)
std::string refusal(const std::string& material, const std::string& coeffs)
{
    const foamTraps traps;
    try
    {
        materialModel::New(materialDict(material, coeffs));
    }
    catch (const Foam::error& err)
    {
        return err.message();
    }
    return "";
}

const std::string elastic("rho 1000; E 1e6; nu 0.3;");
const std::string water("rho 1000; mu 1e-3; c 20;");

} // End anonymous namespace


TEST(materialModel, OutOfRangeCoefficientsRefusedWithTheirRange)
{
    const std::pair<std::string, std::string> cases[][2] =
    {
        {{"linearElastic", "rho 1000; E 1e6; nu 0.5;"},
         {"nu = 0.5", "allowed: 0 <= nu < 0.5"}},
        {{"linearElastic", "rho 1000; E 1e6; nu -1;"},
         {"nu = -1", "allowed: 0 <= nu < 0.5"}},
        {{"linearElastic", "rho 1000; E 1e300; nu 0.3;"},
         {"E = 1e+300", "allowed: 0 < E <= 1e+13 [Pa]"}},
        {{"linearElastic", "rho 1e300; E 1e6; nu 0.3;"},
         {"rho = 1e+300", "allowed: 0.001 <= rho <= 100000 [kg/m^3]"}},
        {{"Newtonian", "rho 1000; mu 1e-3; c 1e300;"},
         {"c = 1e+300", "allowed: 0.001 <= c <= 100000 [m/s]"}},
        {{"Newtonian", "rho 1000; mu 1e-3; c 0;"},
         {"c = 0", "allowed: 0.001 <= c"}},
        {{"Newtonian", water + " gamma 1e300;"},
         {"gamma = 1e+300", "allowed: 1 <= gamma <= 100"}},
        {{"Newtonian", water + " pMin -1e300;"},
         {"pMin = -1e+300", "allowed: -1e+13 <= pMin <= 0 [Pa]"}},
        {{"Bingham", water + " tauY 10; shearModulus 1e300;"},
         {"shearModulus = 1e+300", "allowed: 0 <= shearModulus <= 1e+13"}},
        {{"DruckerPrager", elastic + " frictionAngle 90;"},
         {"frictionAngle = 90", "allowed: 0 <= frictionAngle < 90 [deg]"}},
        {{"DruckerPrager", elastic + " frictionAngle 30; cohesion 1e300;"},
         {"cohesion = 1e+300", "allowed: 0 <= cohesion <= 1e+13 [Pa]"}},
        {{"DruckerPrager", elastic + " frictionAngle 30; dilatancyAngle 40;"},
         {"dilatancyAngle = 40", "dilatancyAngle <= frictionAngle"}},
        {{"Bingham", water + " tauY 1e300; m 1e300; shearModulus 0;"},
         {"viscosity of inf Pa s", "allowed: coefficients whose"}},
    };
    for (const auto& c : cases)
    {
        const std::string why(refusal(c[0].first, c[0].second));
        EXPECT_NE(why.find(c[1].first), std::string::npos)
            << c[0].first << " " << c[0].second << ": " << why;
        EXPECT_NE(why.find(c[1].second), std::string::npos)
            << c[0].first << " " << c[0].second << ": " << why;
    }
}


TEST(materialModel, EndsOfTheRangesGiveFiniteWaveSpeeds)
{
    const foamTraps traps;
    // Nearly incompressible, stiffest and lightest: the P-wave speed
    // sqrt((K + 4G/3)/rho) of its closed form
    const scalar E = 1e13, nu = 0.4999999, rho = 1e-3;
    const autoPtr<materialModel> solid
    (
        materialModel::New
        (
            materialDict
            (
                "linearElastic",
                "rho 1e-3; E 1e13; nu 0.4999999;"
            )
        )
    );
    const scalar K = E/(3*(1 - 2*nu)), G = E/(2*(1 + nu));
    constexpr double tol = 1e-12; // round-off of a few operations
    EXPECT_NEAR(solid->waveSpeed()/std::sqrt((K + 4*G/3)/rho), 1, tol);
    EXPECT_TRUE(std::isfinite(solid->restJ(1e13)));

    const autoPtr<materialModel> fluid
    (
        materialModel::New
        (
            materialDict("Bingham", "rho 1e5; mu 1; tauY 1e13; c 1e-3;")
        )
    );
    EXPECT_TRUE(std::isfinite(fluid->waveSpeed()));
    EXPECT_GT(fluid->waveSpeed(), 0);
    EXPECT_TRUE(std::isfinite(fluid->restJ(1e13)));
}


// ************************************************************************* //
