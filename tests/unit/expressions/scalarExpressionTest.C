/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    Expressions: precedence and associativity, every function against the
    C++ standard library, the ternary of a piecewise slope, a hemispherical
    mound, the order of the variables, exact derivatives (every function
    against its closed-form derivative, the taken branch at kinks, no trap
    where the value is finite), parse errors that point at the error,
    constants folded to NaN and inf under the solvers' floating-point
    traps, bounds over boxes that hold every value taken in them (every
    function and operator, random boxes, and where a value may be NaN)
    and are tight for the slope and the hemisphere, and OpenMP evaluation
    that agrees with serial evaluation bit for bit. Prints the evaluations
    per second of the hemisphere.

\*---------------------------------------------------------------------------*/

#include "scalarExpression.H"
#include "fpTrapsHeld.H"
#include "IStringStream.H"
#include "OStringStream.H"
#include "testCase.H"
#include <gtest/gtest.h>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <random>
#include <tuple>

using namespace Foam;

namespace
{

// The expressions call the same libm functions as the references: they
// agree to round-off of one operation
constexpr double relTol = 1e-15;

const char* const hemisphere = "sqrt(max(25 - (x-25)^2 - (y-25)^2, 0))";


double eval
(
    const std::string& expr,
    const double x = 2,
    const double y = 3
)
{
    const double xy[2] = {x, y};
    return scalarExpression(expr, {"x", "y"}, "test").value(xy);
}


void expectRel(const std::string& expr, const double got, const double ref)
{
    EXPECT_NEAR(got, ref, relTol*std::abs(ref)) << expr;
}


//- The message of the parse error of expr read from a dictionary
std::string dictError(const std::string& expr)
{
    dictionary dict;
    dict.add("height", string(expr));
    return foamErrorMessage
    (
        [&]{ scalarExpression(dict, "height", {"x", "y"}); }
    );
}

//- The value and the derivative along variable var of expr(x, y)
std::pair<double, double> derivative
(
    const std::string& expr,
    const double x,
    const double y,
    const label var
)
{
    const double xy[2] = {x, y};
    double d = 0;
    const double v =
        scalarExpression(expr, {"x", "y"}, "test").value(xy, var, d);
    return {v, d};
}

} // End anonymous namespace


// A derivative is a few roundings of one operation away from its closed
// form
constexpr double derivativeTol = 1e-14;


TEST(scalarExpression, DerivativesMatchTheClosedForms)
{
    // f(a) and f'(a) of every function of one argument, at x = a and,
    // through 2 y - 1, along y (the chain rule)
    using fn1 = std::function<double(double)>;
    const std::vector<std::pair<std::string, fn1>> unary =
    {
        {"sqrt", [](double a){ return 0.5/std::sqrt(a); }},
        {"exp", [](double a){ return std::exp(a); }},
        {"log", [](double a){ return 1/a; }},
        {"log10", [](double a){ return 1/(a*std::log(10.0)); }},
        {"sin", [](double a){ return std::cos(a); }},
        {"cos", [](double a){ return -std::sin(a); }},
        {"tan", [](double a){ return 1/(std::cos(a)*std::cos(a)); }},
        {"asin", [](double a){ return 1/std::sqrt(1 - a*a); }},
        {"acos", [](double a){ return -1/std::sqrt(1 - a*a); }},
        {"atan", [](double a){ return 1/(1 + a*a); }},
        {"sinh", [](double a){ return std::cosh(a); }},
        {"cosh", [](double a){ return std::sinh(a); }},
        {"tanh", [](double a){ return 1 - std::tanh(a)*std::tanh(a); }},
        {"abs", [](double a){ return a > 0 ? 1.0 : -1.0; }},
        {"floor", [](double){ return 0.0; }},
        {"ceil", [](double){ return 0.0; }},
        {"deg2rad", [](double){ return M_PI/180; }},
        {"rad2deg", [](double){ return 180/M_PI; }},
        {"sign", [](double){ return 0.0; }}
    };
    for (const auto& f : unary)
    {
        for (const double a : {0.3, 0.7, -0.45, 1.7, 12.5})
        {
            if (!std::isfinite(eval(f.first + "(x)", a)))
            {
                continue;
            }
            const std::string expr = f.first + "(x)";
            const auto vd = derivative(expr, a, 0, 0);
            EXPECT_EQ(vd.first, eval(expr, a)) << expr << " at " << a;
            const double exact = f.second(a);
            EXPECT_NEAR(vd.second, exact, derivativeTol*(1 + std::abs(exact)))
                << expr << "' at " << a;
            const std::string chain = f.first + "(2*y - 1)";
            const double ref = 2*f.second(a);
            EXPECT_NEAR
            (
                derivative(chain, 0, (a + 1)/2, 1).second,
                ref,
                derivativeTol*(1 + std::abs(ref))
            )   << chain << "' at y = " << (a + 1)/2;
            EXPECT_EQ(derivative(expr, a, 0, 1).second, 0)
                << expr << " does not depend on y";
        }
    }

    // Functions of two arguments and the operators: d/dx and d/dy
    struct case2
    {
        std::string expr;
        double x, y, dx, dy;
    };
    const double x = 1.3, y = 0.6;
    const double h = std::hypot(x, y);
    const std::vector<case2> binary =
    {
        {"x + y", x, y, 1, 1},
        {"x - 3*y", x, y, 1, -3},
        {"x*y", x, y, y, x},
        {"x/y", x, y, 1/y, -x/(y*y)},
        {"x^y", x, y, y*std::pow(x, y - 1), std::pow(x, y)*std::log(x)},
        {"x^2", x, y, 2*x, 0},
        {"pow(-x, 3)", x, y, -3*x*x, 0},
        {"atan2(y, x)", x, y, -y/(h*h), x/(h*h)},
        {"hypot(x, y)", x, y, x/h, y/h},
        {"min(x, y)", x, y, 0, 1},
        {"max(x, y)", x, y, 1, 0},
        {"-x + !y", x, y, -1, 0},
        {"x < y || x > 2*y", x, y, 0, 0},
        // The slidingToWall ground: the taken branch, also at the kink
        {"x <= 10 ? 10 - x/3 : 10 - 10/3", 3, y, -1.0/3, 0},
        {"x <= 10 ? 10 - x/3 : 10 - 10/3", 10, y, -1.0/3, 0},
        {"x <= 10 ? 10 - x/3 : 10 - 10/3", 10.5, y, 0, 0},
        // A hemisphere of radius 5: -(x - 25)/h on it, 0 outside and on
        // the rim (sqrt at 0)
        {hemisphere, 28, 25, -3.0/4, 0},
        {hemisphere, 27, 26, -2/(2*std::sqrt(5.0)), -1/(2*std::sqrt(5.0))},
        {hemisphere, 30, 25, 0, 0},
        {hemisphere, 40, 25, 0, 0}
    };
    for (const case2& c : binary)
    {
        const auto dX = derivative(c.expr, c.x, c.y, 0);
        const auto dY = derivative(c.expr, c.x, c.y, 1);
        EXPECT_EQ(dX.first, eval(c.expr, c.x, c.y)) << c.expr;
        EXPECT_NEAR(dX.second, c.dx, derivativeTol*(1 + std::abs(c.dx)))
            << "d/dx " << c.expr << " at (" << c.x << " " << c.y << ")";
        EXPECT_NEAR(dY.second, c.dy, derivativeTol*(1 + std::abs(c.dy)))
            << "d/dy " << c.expr << " at (" << c.x << " " << c.y << ")";
    }
}


TEST(scalarExpression, DerivativesRaiseNoTrapWhereTheValueIsFinite)
{
    // Under the solvers' traps: where the derivative is infinite or
    // undefined it is 0, and large or tiny values are not squared
    const solverFpTraps traps;
    struct case1
    {
        std::string expr;
        double x, y, value, dx;
    };
    const double tiny = 1e-170, huge = 1e200;
    const std::vector<case1> cases =
    {
        {"x^0.5", 0, 0, 0, 0},
        {"x^0", 0, 0, 1, 0},
        {"x^1", 0, 0, 0, 1},
        {"x^3", 0, 0, 0, 0},
        {"y^x", 2, 0, 0, 0},
        {"y^x", 2, -2, 4, 0},
        {"abs(x)", 0, 0, 0, 0},
        {"sqrt(x)", 0, 0, 0, 0},
        {"asin(x)", 1, 0, M_PI/2, 0},
        {"acos(x)", -1, 0, M_PI, 0},
        {"x/y", 1, tiny, 1/tiny, 1/tiny},
        {"atan(x)", huge, 0, M_PI/2, 0},
        {"atan2(y, x)", huge, huge, M_PI/4, -0.5/huge}
    };
    for (const case1& c : cases)
    {
        const auto vd = derivative(c.expr, c.x, c.y, 0);
        EXPECT_NEAR(vd.first, c.value, relTol*std::abs(c.value)) << c.expr;
        EXPECT_NEAR(vd.second, c.dx, derivativeTol*std::abs(c.dx))
            << "d/dx " << c.expr << " at (" << c.x << " " << c.y << ")";
    }
}


TEST(scalarExpression, PrecedenceAndAssociativityFollowC)
{
    // {expression, value}: literals (folded while parsing) and x = 2, y = 3
    const std::vector<std::pair<std::string, double>> cases =
    {
        {"1 + 2*3", 7}, {"x + y*4", 14}, {"(1 + 2)*3", 9},
        {"2^3^2", 512}, {"x^y^x", 512}, {"(x^y)^x", 64},
        {"-2^2", -4}, {"-x^2", -4}, {"(-x)^2", 4}, {"x^-1", 0.5},
        {"2^-2^2", 0.0625}, {"10 - 4 - 3", 3}, {"10 - x - y", 5},
        {"24/4/3", 2}, {"24/x/y", 4}, {"x*y/x", 3}, {"8/x*4", 16},
        {"1 - x + y", 2}, {"x*y^2", 18}, {"x - y*x + 1", -3}, {"- -x", 2},
        {"+-+x", -2}, {"x*-y", -6}, {"x + 2 < 5", 1}, {"x < y == 1", 1},
        {"x >= y", 0}, {"x <= 2", 1}, {"x > 1.5", 1}, {"x != 2", 0},
        {"0 || 1 && 0", 0}, {"1 || 0 && 0", 1}, {"x && !y", 0},
        {"!0 + 1", 2}, {"!x + 1", 1}, {"x ? 2 : 3", 2},
        {"1 ? 2 : 3 ? 4 : 5", 2}, {"0 ? 2 : 0 ? 4 : 5", 5},
        {"x - 2 ? 1 : y - 3 ? 4 : 5", 5}, {"x > 0 ? y > 3 ? 6 : 7 : 8", 7},
        {"x < 0 ? 1 : 2 + 3", 5}, {"(x < 0 ? 1 : 2) + 3", 5},
        {"(x > 0 ? 1 : 2) + 3", 4}, {"2^(x > 0 ? 1 : 2)", 2},
        {"x < 0 ? 1 : 2^2", 4}, {".5 + 2.5 + 1. + 1e-3 + 2.5E+1", 29.001},
        {"pi", M_PI}, {"e", M_E}, {" \t x\n*( y+1 ) ", 8}
    };
    for (const auto& c : cases)
    {
        expectRel(c.first, eval(c.first), c.second);
    }
}


TEST(scalarExpression, FunctionsMatchTheStandardLibrary)
{
    using fn1 = std::function<double(double)>;
    const std::vector<std::pair<std::string, fn1>> unary =
    {
        {"sqrt", [](double a){ return std::sqrt(a); }},
        {"exp", [](double a){ return std::exp(a); }},
        {"log", [](double a){ return std::log(a); }},
        {"log10", [](double a){ return std::log10(a); }},
        {"sin", [](double a){ return std::sin(a); }},
        {"cos", [](double a){ return std::cos(a); }},
        {"tan", [](double a){ return std::tan(a); }},
        {"asin", [](double a){ return std::asin(a); }},
        {"acos", [](double a){ return std::acos(a); }},
        {"atan", [](double a){ return std::atan(a); }},
        {"sinh", [](double a){ return std::sinh(a); }},
        {"cosh", [](double a){ return std::cosh(a); }},
        {"tanh", [](double a){ return std::tanh(a); }},
        {"abs", [](double a){ return std::abs(a); }},
        {"floor", [](double a){ return std::floor(a); }},
        {"ceil", [](double a){ return std::ceil(a); }},
        {"deg2rad", [](double a){ return a*M_PI/180; }},
        {"rad2deg", [](double a){ return a*180/M_PI; }},
        {"sign", [](double a){ return a >= 0 ? 1.0 : -1.0; }}
    };
    const double args[] = {0.3, 0.7, 0.9999, 1.7, 12.5};
    for (const auto& f : unary)
    {
        for (const double a : args)
        {
            for (const double x : {a, -a})
            {
                const double ref = f.second(x);
                if (std::isfinite(ref))
                {
                    const std::string expr = f.first + "(x)";
                    expectRel(expr, eval(expr, x), ref);
                    expectRel(expr, eval(f.first + "(y)", 0, x), ref);
                }
            }
        }
    }
    EXPECT_EQ(eval("sign(x)", 0), 1) << "sign(0) is 1, as Foam::sign";
    EXPECT_TRUE(std::isnan(eval("sqrt(x)", -1))) << "as std::sqrt";

    using fn2 = std::function<double(double, double)>;
    const std::vector<std::pair<std::string, fn2>> binary =
    {
        {"atan2", [](double a, double b){ return std::atan2(a, b); }},
        {"min", [](double a, double b){ return std::min(a, b); }},
        {"max", [](double a, double b){ return std::max(a, b); }},
        {"pow", [](double a, double b){ return std::pow(a, b); }},
        {"hypot", [](double a, double b){ return std::hypot(a, b); }}
    };
    for (const auto& f : binary)
    {
        for (const double x : {0.3, -1.7, 2.0, 12.5})
        {
            for (const double y : {0.5, -2.0, 2.0, 3.25})
            {
                const double ref = f.second(x, y);
                if (std::isfinite(ref))
                {
                    const std::string expr = f.first + "(x, y)";
                    expectRel(expr, eval(expr, x, y), ref);
                    if (f.first == "pow")
                    {
                        expectRel("x^y", eval("x^y", x, y), ref);
                    }
                }
            }
        }
    }
}


TEST(scalarExpression, TernaryGivesThePiecewiseSlope)
{
    dictionary dict(IStringStream("Z \"x <= 10 ? 10 - x/3 : 6.67\";")());
    const scalarExpression Z(dict, "Z", {"x"});

    // {x, Z}: the slope up to x = 10, flat after
    const std::vector<std::pair<double, double>> points =
    {
        {-3, 11}, {0, 10}, {3, 9}, {10, 10 - 10.0/3}, {10.000001, 6.67},
        {20, 6.67}
    };
    for (const auto& p : points)
    {
        EXPECT_NEAR(Z.value(&p.first), p.second, relTol*p.second)
            << "x = " << p.first;
    }
}


TEST(scalarExpression, HemisphereHasRadiusFiveAboutItsCentre)
{
    dictionary dict;
    dict.add("height", string(hemisphere));
    const scalarExpression h(dict, "height", {"x", "y"});

    // {x, y, height}: top, on the sphere, on the rim, outside
    const std::vector<std::array<double, 3>> points =
    {
        {25, 25, 5}, {28, 25, 4}, {25, 21, 3}, {27, 26, 2*std::sqrt(5.0)},
        {28, 29, 0}, {20, 25, 0}, {100, -3, 0}
    };
    for (const auto& p : points)
    {
        EXPECT_NEAR(h.value(p.data()), p[2], relTol*p[2])
            << "(" << p[0] << " " << p[1] << ")";
    }
}


// Every function and operator, over 400 random boxes each (half-widths
// 1e-8 to 10 about centres in [-8, 8]^2, some of them points): every value
// the expression takes at 300 points of the box (its corners, points one
// ulp inside them, random ones) lies within its bounds, and is not NaN,
// unless the bounds are [-inf, inf]; each expression is bounded over most
// boxes, and the solvers' traps stay quiet
TEST(scalarExpression, BoundsHoldEveryValueOverRandomBoxes)
{
    const std::vector<std::string> exprs =
    {
        "x + y", "x - 2*y", "x*y", "x/y", "x^2 - y", "(x - y)^3", "x^-2",
        "pow(x, y)", "pow(x, 0.5)", "pow(x, 3) + pow(y, -3)", "pow(y, 4)",
        "2^x", "abs(x)*y", "sqrt(x)", "exp(x/2)", "log(x)",
        "log10(abs(x) + 1)", "sin(3*x) + cos(y)", "sin(x*y)", "tan(x)",
        "asin(x/6)", "acos(y/6)", "atan(x*y)", "sinh(x)", "cosh(x - y)",
        "tanh(x)", "floor(x) + ceil(y)", "deg2rad(x) + rad2deg(y)",
        "sign(x)*y", "atan2(y, x)", "hypot(x, y)", "min(x, y) - max(x, -y)",
        "max(sqrt(x), 0)", "max(0, sqrt(x))", "x <= 1 ? 2 - x/3 : y",
        "x < y && y > 0 || !(x == 1) ? sin(x) : -y", "x != y", "-x >= y",
        "y < 0 ? (x < 0 ? x : 2*x) : (x > 1 ? -x : x*y)",
        "x <= 10 ? 10 - x/3 : 10 - 10/3", hemisphere,
        "(x < 0 ? sqrt(-x) : sqrt(x)) + 1e300*y"
    };
    const solverFpTraps traps;
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(0, 1);
    for (const std::string& expr : exprs)
    {
        const scalarExpression f(expr, {"x", "y"}, "test");
        label bounded = 0;
        for (label box = 0; box < 400; ++box)
        {
            scalarMinMax r[2];
            for (scalarMinMax& ri : r)
            {
                const double c = -8 + 16*u(rng);
                const double h = box%10 ? std::pow(10.0, -8 + 9*u(rng)) : 0;
                ri = scalarMinMax(c - h, c + h);
            }
            const scalarMinMax b(f.bounds(r));
            if (b.min() == -INFINITY && b.max() == INFINITY)
            {
                continue;
            }
            ++bounded;
            fpTrapsHeld masked;
            for (label k = 0; k < 300; ++k)
            {
                double xy[2];
                for (int d = 0; d < 2; ++d)
                {
                    const double lo = r[d].min(), hi = r[d].max();
                    const int corner = (k >> d) & 1;
                    xy[d] =
                        k < 4 ? (corner ? hi : lo)
                      : k < 8
                      ? std::nextafter(corner ? hi : lo, lo + (hi - lo)/2)
                      : lo + (hi - lo)*u(rng);
                    xy[d] = std::min(std::max(xy[d], lo), hi);
                }
                const double v = f.value(xy);
                EXPECT_TRUE(b.min() <= v && v <= b.max())
                    << expr << " at (" << xy[0] << " " << xy[1] << ") = " << v
                    << " outside [" << b.min() << ", " << b.max() << "]";
            }
        }
        EXPECT_GT(bounded, 100) << expr;
    }
}


// Where a value may be NaN, and a later operation takes it for a number
// (a comparison, min, max, the ternary's other branch), the bounds still
// hold every value: sin and cos of an exp that overflows in the box, NaN
// constants (0/0, acos(2)) and an expression that is one. At the boxes'
// corners and 200 points along their diagonal every value is within the
// bounds, and a NaN value only within [-inf, inf]
TEST(scalarExpression, BoundsHoldWhereAValueMayBeNaN)
{
    const solverFpTraps traps;
    const std::vector<std::tuple<std::string, scalarMinMax, scalarMinMax>>
        cases =
    {
        {"sin(exp(x)) < 2 ? 0 : 100", {700, 710}, {0, 1}},
        {"cos(exp(x)) > 2 ? 100 : 0", {700, 710}, {0, 1}},
        {"x > 0 ? 1 : 0/0", {-1, 1}, {0, 1}},
        {"min(x, (y >= 1e-300) ? !x : acos(2))", {-1, 1}, {0, 1}},
        {"exp(0/0 + x)", {-1, 1}, {0, 1}},
        {"0/0", {-1, 1}, {0, 1}}
    };
    for (const auto& c : cases)
    {
        const scalarExpression f(std::get<0>(c), {"x", "y"}, "test");
        const scalarMinMax r[2] = {std::get<1>(c), std::get<2>(c)};
        const scalarMinMax b(f.bounds(r));
        const bool whole = b.min() == -INFINITY && b.max() == INFINITY;
        fpTrapsHeld masked;
        for (label k = 0; k <= 203; ++k)
        {
            const double t = k < 4 ? (k & 1) : (k - 4)/199.0;
            const double ty = k < 4 ? (k >> 1) : t;
            const double xy[2] =
            {
                r[0].min() + t*(r[0].max() - r[0].min()),
                r[1].min() + ty*(r[1].max() - r[1].min())
            };
            const double v = f.value(xy);
            EXPECT_TRUE(v == v ? b.min() <= v && v <= b.max() : whole)
                << std::get<0>(c) << " at (" << xy[0] << " " << xy[1]
                << ") = " << v << " outside [" << b.min() << ", "
                << b.max() << "]";
        }
    }
}


// The bounds of the paper's piecewise slope are its values at the ends of
// a piece; where a box straddles the kink, both pieces over the whole box
// (the slope continued to the box's end below, its value at the box's
// start above); the hemisphere's highest about its top, its radius
TEST(scalarExpression, BoundsOfTheSlopeAndTheHemisphereAreTight)
{
    const scalarExpression Z
    (
        "x <= 10 ? 10 - x/3 : 10 - 10/3", {"x", "y"}, "test"
    );
    const scalarMinMax onSlope[2] = {{2, 3}, {0, 1}};
    EXPECT_EQ(Z.bounds(onSlope).min(), 10 - 3.0/3);
    EXPECT_EQ(Z.bounds(onSlope).max(), 10 - 2.0/3);
    const scalarMinMax acrossKink[2] = {{9, 11}, {0, 1}};
    EXPECT_EQ(Z.bounds(acrossKink).min(), 10 - 11.0/3);
    EXPECT_EQ(Z.bounds(acrossKink).max(), 10 - 9.0/3);
    const scalarMinMax point[2] = {{7.3, 7.3}, {2, 2}};
    const double xy[2] = {7.3, 2};
    EXPECT_EQ(Z.bounds(point).min(), Z.value(xy));
    EXPECT_EQ(Z.bounds(point).max(), Z.value(xy));

    const scalarExpression h(hemisphere, {"x", "y"}, "test");
    const scalarMinMax aboutTop[2] = {{24.5, 25.5}, {24, 25}};
    EXPECT_EQ(h.bounds(aboutTop).max(), 5);
    EXPECT_NEAR(h.bounds(aboutTop).min(), std::sqrt(25 - 0.25 - 1), 1e-14);
}


TEST(scalarExpression, VariablesAreTakenInTheGivenOrder)
{
    const std::string expr = "x - 2*y + 10*t";
    const double xyt[3] = {1, 2, 3};
    const double txy[3] = {3, 1, 2};
    const double expected = 1 - 2*2 + 10*3;
    EXPECT_NEAR
    (
        scalarExpression(expr, {"x", "y", "t"}, "xyt").value(xyt),
        expected,
        relTol*expected
    );
    EXPECT_NEAR
    (
        scalarExpression(expr, {"t", "x", "y"}, "txy").value(txy),
        expected,
        relTol*expected
    );

    const scalarExpression f("x + 0*t", {"x", "y", "t"}, "f");
    EXPECT_TRUE(f.dependsOn("x"));
    EXPECT_TRUE(f.dependsOn("t"));
    EXPECT_FALSE(f.dependsOn("y"));
    EXPECT_FALSE(f.dependsOn("z"));

    // A variable hides the constant e
    const double e = 3;
    EXPECT_NEAR(scalarExpression("2*e", {"e"}, "e").value(&e), 6, 6*relTol);

    OStringStream os;
    f.write(os);
    EXPECT_EQ(std::string(os.str()), "\"x + 0*t\"");
}


TEST(scalarExpression, ParseErrorsNameTheKeywordAndPointAtTheError)
{
    // {expression, what is wrong, column}
    const std::vector<std::tuple<std::string, std::string, int>> cases =
    {
        {"x + z", "unknown variable z", 5},
        {"x + foo(1)", "unknown function foo", 5},
        {"min(x)", "function min takes 2 argument(s), found 1", 1},
        {"2*sqrt(x, y)", "function sqrt takes 1 argument(s), found 2", 3},
        {"sqrt + 1", "expected '(' after the function sqrt, found '+'", 6},
        {"(x + 1", "expected ')' (unbalanced parentheses), found the end", 7},
        {"max(x, (y)",
            "expected ')' or ',' (unbalanced parentheses), found the end", 11},
        {"x + 1)", "unbalanced ')'", 6},
        {"x y", "unexpected 'y'", 3},
        {"x = 1", "unexpected '='", 3},
        {"x & y", "unexpected '&'", 3},
        {"x + ", "expected a value, found the end", 5},
        {"x ? 1", "expected ':' of the '?', found the end", 6},
        {"1e", "unexpected 'e'", 2},
        {"1e999", "number out of range", 1},
        {"", "empty expression", 1},
        {"  \t ", "empty expression", 1},
        {std::string(150, '(') + "x" + std::string(150, ')'),
            "nested too deeply", 101},
    };
    for (const auto& c : cases)
    {
        const std::string& expr = std::get<0>(c);
        const int column = std::get<2>(c);
        const std::string msg = dictError(expr);
        const std::string where =
            std::get<1>(c) + " at column " + std::to_string(column);
        const std::string caret =
            "\n    " + std::string(column - 1, ' ') + "^\n";

        EXPECT_NE(msg.find("keyword height"), std::string::npos) << msg;
        EXPECT_NE(msg.find(where), std::string::npos) << where << '\n' << msg;
        EXPECT_NE(msg.find(caret), std::string::npos) << msg;
        EXPECT_NE(msg.find("Variables: x y\n"), std::string::npos) << msg;
        const std::string functions2 =
            "Functions of (a, b): atan2 min max pow hypot\n";
        EXPECT_NE(msg.find(functions2), std::string::npos) << msg;
    }

    // Too many operands waiting: x+(x+(x+ ... 70 deep
    std::string deep("x");
    for (int i = 0; i < 70; ++i)
    {
        deep = "x+(" + deep + ")";
    }
    EXPECT_NE(dictError(deep).find("needs a stack deeper than maxStack = 64"),
        std::string::npos);

    // The string constructor names its description instead
    const std::string msg = foamErrorMessage
    (
        [&]{ scalarExpression("x + z", {"x"}, "inflow hydrograph"); }
    );
    EXPECT_NE(msg.find("for inflow hydrograph: unknown variable z at column 5"),
        std::string::npos) << msg;

    // The dictionary error is a FatalIOError on the dictionary's file
    dictionary dict;
    dict.name() = "constant/topographyDict";
    dict.add("height", string("x + z"));
    std::string file;
    try
    {
        scalarExpression(dict, "height", {"x", "y"});
    }
    catch (const IOerror& err)
    {
        file = err.ioFileName();
    }
    EXPECT_EQ(file, "constant/topographyDict");
}


TEST(scalarExpression, ConstantsFoldUnderTheSolversTrapsToNaNAndInf)
{
    // Folding 1/0 or an overflow while parsing was a SIGFPE under the
    // solvers' traps; it is a value now, found where it is evaluated
    const solverFpTraps traps;
    const scalarExpression inf("x + 1/0", {"x"}, "test");
    const scalarExpression overflow("1e300*1e300 - x", {"x"}, "test");
    const scalarExpression nan("x*sqrt(-1)", {"x"}, "test");
    const double x = 2;
    fpTrapsHeld masked;
    EXPECT_TRUE(std::isinf(inf.value(&x)));
    EXPECT_TRUE(std::isinf(overflow.value(&x)));
    EXPECT_TRUE(std::isnan(nan.value(&x)));
}


TEST(scalarExpression, OpenMPAndSerialLoopsAgreeBitForBit)
{
    const scalarExpression h(hemisphere, {"x", "y"}, "hemisphere");
    const label n = 1000000;
    const auto point = [](const label i, double xy[2])
    {
        xy[0] = 20 + 1e-5*i;            // 20 to 30
        xy[1] = 25 + 4*std::sin(1e-3*i);
    };

    std::vector<double> serial(n), parallel(n);
    for (label i = 0; i < n; ++i)
    {
        double xy[2];
        point(i, xy);
        serial[i] = h.value(xy);
    }
    #pragma omp parallel for num_threads(4) schedule(static, 1000)
    for (label i = 0; i < n; ++i)
    {
        double xy[2];
        point(i, xy);
        parallel[i] = h.value(xy);
    }

    // Same code on the same input: identical, so the tolerance is zero
    label nDiffer = 0;
    for (label i = 0; i < n; ++i)
    {
        nDiffer += (serial[i] != parallel[i]);
    }
    EXPECT_EQ(nDiffer, 0);

    // And they are the hemisphere: (x, y) = (25, 25 + 4 sin(500)) at n/2
    const double dy = 4*std::sin(500.0);
    const double h2 = std::sqrt(25 - dy*dy);
    EXPECT_NEAR(serial[n/2], h2, 4*relTol*h2) << "a few operations";
}


TEST(scalarExpressionBenchmark, HemisphereEvaluationSpeedIsReported)
{
    const scalarExpression h(hemisphere, {"x", "y"}, "hemisphere");
    const label n = 10000000;
    using clock = std::chrono::steady_clock;

    double sum = 0;
    const clock::time_point start = clock::now();
    for (label i = 0; i < n; ++i)
    {
        const double xy[2] = {20 + 1e-6*i, 25 + 1e-7*i};
        sum += h.value(xy);
    }
    const double seconds =
        std::chrono::duration<double>(clock::now() - start).count();

    double sumNative = 0;
    const clock::time_point startNative = clock::now();
    for (label i = 0; i < n; ++i)
    {
        const double x = 20 + 1e-6*i;
        const double y = 25 + 1e-7*i;
        sumNative +=
            std::sqrt(std::max(25 - std::pow(x - 25, 2)
          - std::pow(y - 25, 2), 0.0));
    }
    const double secondsNative =
        std::chrono::duration<double>(clock::now() - startNative).count();

    std::cout
        << "scalarExpression: " << hemisphere << ": " << n/seconds/1e6
        << " million evaluations/s (compiled C++: "
        << n/secondsNative/1e6 << " million/s)" << std::endl;

    // Sums of 1e7 terms of O(1) in the same order
    constexpr double sumTol = 1e-12;
    EXPECT_NEAR(sum, sumNative, sumTol*sumNative);
}


// ************************************************************************* //
