/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Application
    expressionCost

Description
    The cost of one evaluation of the tutorials' topography and release
    expressions with dampm's scalarExpression and with OpenFOAM v1912's
    expressions::fieldExpr::parseDriver (libOpenFOAM), per point and over a
    field of N points, the cost of the terrain gradient (scalarExpression's
    exact derivative; v1912 gives none, so a central difference of four
    more field evaluations), the largest difference of the two parsers'
    values, and the error messages of both for three typical mistakes.

    Built and run by Allrun; prints a Markdown report. Times are the best of
    a few repeats (shared cores). Fails if the two parsers' values differ
    beyond round-off.

Usage
    expressionCost [N] [repeats]

\*---------------------------------------------------------------------------*/

#include "scalarExpression.H"
#include "fieldExprDriver.H"
#include "error.H"
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

using namespace Foam;

namespace
{

//- One expression in both syntaxes, and what it is
struct expressionPair
{
    const char* name;
    const char* dampm;
    const char* openfoam;
};

//- The tutorials' expressions (grep expression tutorials/); v1912 has no ^
//  for scalars and no deg2rad(a), and writes the constant pi as pi()
const expressionPair tutorialExpressions[] =
{
    {
        "frictionalIncline Z",
        "15 - tan(deg2rad(30))*x",
        "15 - tan(degToRad()*30)*x"
    },
    {
        "slidingToWall Z",
        "x <= 10 ? 10 - x/3 : 10 - 10/3",
        "x <= 10 ? 10 - x/3 : 10 - 10/3"
    },
    {
        "hillside release h",
        "3.08*(1 - ((x - 300)/30)^2 - ((y - 150)/40)^2)",
        "3.08*(1 - sqr((x - 300)/30) - sqr((y - 150)/40))"
    },
    {
        "semisphere release h",
        "sqrt(max(25 - (x-25)^2 - (y-25)^2, 0))",
        "sqrt(max(25 - sqr(x-25) - sqr(y-25), 0))"
    }
};


//- v1912's field driver with x and y set as field variables
class fieldDriver
:
    public expressions::fieldExpr::parseDriver
{
public:

    explicit fieldDriver(const label n)
    :
        parseDriver(n)
    {}

    void setVariable(const word& name, const scalarField& f)
    {
        variables_.set(name, expressions::exprResult(f));
    }

    const scalarField& values() const
    {
        return result().cref<scalar>();
    }
};


//- Best time of repeats runs of fn [s]
double bestTime(const int repeats, const std::function<void()>& fn)
{
    double best = 1e300;
    for (int r = 0; r < repeats; ++r)
    {
        const auto t0 = std::chrono::steady_clock::now();
        fn();
        const std::chrono::duration<double> dt =
            std::chrono::steady_clock::now() - t0;
        best = std::min(best, dt.count());
    }
    return best;
}


//- The message of the FatalError or FatalIOError fn raises
std::string errorText(const std::function<void()>& fn)
{
    try
    {
        fn();
    }
    catch (const IOerror& err)
    {
        return err.message()
          + (err.ioFileName().empty() ? "" : "\nfile: " + err.ioFileName());
    }
    catch (const error& err)
    {
        return err.message();
    }
    return "(no error)";
}


//- A sink the optimiser cannot drop
volatile double sink = 0;

} // End anonymous namespace


int main(int argc, char *argv[])
{
    const label n = (argc > 1 ? std::atoi(argv[1]) : 100000);
    const int repeats = (argc > 2 ? std::atoi(argv[2]) : 5);
    // Per-point calls of v1912's driver parse each time: fewer of them
    const label nPoint = std::min<label>(n, 20000);
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    // Points over the tutorials' domains: x in [0, 400), y in [0, 300)
    scalarField x(n), y(n);
    for (label i = 0; i < n; ++i)
    {
        x[i] = 400.0*((i*7919) % n)/n;
        y[i] = 300.0*((i*104729) % n)/n;
    }
    const wordList vars({"x", "y"});
    constexpr double h = 1e-3;      // central-difference step [m]
    constexpr double sameTol = 1e-9;  // round-off of values up to 1e3 m
    double worstDiff = 0;

    std::printf
    (
        "## Cost per evaluation, N = %d points (best of %d)\n\n"
        "| expression | dampm value() [ns/pt] | v1912 driver of size 1 [ns/pt]"
        " | v1912 field [ns/pt]"
        " | dampm value + exact gradient [ns/pt]"
        " | v1912 value + central-difference gradient [ns/pt]"
        " | max abs difference |\n"
        "|---|---|---|---|---|---|---|\n",
        int(n), repeats
    );

    for (const expressionPair& e : tutorialExpressions)
    {
        const scalarExpression ours(e.dampm, vars, e.name);

        // dampm, one point at a time: what the solvers do (parse once, then
        // value() at each node or column)
        scalarField oursValues(n);
        const double tOurs = bestTime(repeats, [&]
        {
            for (label i = 0; i < n; ++i)
            {
                const scalar xy[2] = {x[i], y[i]};
                oursValues[i] = ours.value(xy);
            }
        });

        // dampm with the exact gradient (as expressionTopography::gradient)
        const double tOursGrad = bestTime(repeats, [&]
        {
            double s = 0;
            for (label i = 0; i < n; ++i)
            {
                const scalar xy[2] = {x[i], y[i]};
                scalar dx, dy;
                s += ours.value(xy, 0, dx);
                ours.value(xy, 1, dy);
                s += dx + dy;
            }
            sink = s;
        });

        // v1912, one point at a time: a driver of size 1, x and y uniform;
        // the driver has no compiled form, each evaluation parses
        const std::string theirs(e.openfoam);
        expressions::fieldExpr::parseDriver pointDriver(1);
        const double tTheirs = bestTime(repeats, [&]
        {
            double s = 0;
            for (label i = 0; i < nPoint; ++i)
            {
                pointDriver.addUniformVariable("x", x[i]);
                pointDriver.addUniformVariable("y", y[i]);
                pointDriver.parse(theirs);
                s += pointDriver.result().cref<scalar>()[0];
            }
            sink = s;
        });

        // v1912 over a field of n points
        fieldDriver driver(n);
        driver.setVariable("x", x);
        driver.setVariable("y", y);
        const double tTheirsField = bestTime(repeats, [&]
        {
            driver.parse(theirs);
            sink = driver.values()[n/2];
        });
        driver.parse(theirs);
        double maxDiff = 0;
        for (label i = 0; i < n; ++i)
        {
            maxDiff = std::max
            (
                maxDiff, std::abs(driver.values()[i] - oursValues[i])
            );
        }
        worstDiff = std::max(worstDiff, maxDiff);

        // v1912 value and a central-difference gradient: 5 field evaluations
        const scalarField xp(x + h), xm(x - h), yp(y + h), ym(y - h);
        scalarField grad(n);
        const double tTheirsGrad = bestTime(repeats, [&]
        {
            driver.setVariable("x", x);
            driver.parse(theirs);
            const scalarField Z(driver.values());
            driver.setVariable("x", xp);
            driver.parse(theirs);
            grad = driver.values();
            driver.setVariable("x", xm);
            driver.parse(theirs);
            grad -= driver.values();
            driver.setVariable("x", x);
            driver.setVariable("y", yp);
            driver.parse(theirs);
            grad += driver.values();
            driver.setVariable("y", ym);
            driver.parse(theirs);
            grad -= driver.values();
            driver.setVariable("y", y);
            sink = Z[n/2] + grad[n/2]/(2*h);
        });

        std::printf
        (
            "| %s | %.1f | %.0f | %.1f | %.1f | %.1f | %.2g |\n",
            e.name, 1e9*tOurs/n, 1e9*tTheirs/nPoint,
            1e9*tTheirsField/n, 1e9*tOursGrad/n, 1e9*tTheirsGrad/n, maxDiff
        );
    }

    // Parsing once (construction), as the solvers do at start-up
    {
        const expressionPair& e = tutorialExpressions[2];
        const label nParse = 20000;
        const double tParse = bestTime(repeats, [&]
        {
            for (label i = 0; i < nParse; ++i)
            {
                const scalarExpression ours(e.dampm, vars, e.name);
                sink = ours.variables().size();
            }
        });
        std::printf
        (
            "\nParsing \"%s\" once (scalarExpression's constructor): %.0f ns\n",
            e.dampm, 1e9*tParse/nParse
        );
    }

    // Three typical mistakes
    const expressionPair mistakes[] =
    {
        {
            "unknown variable",
            "15 - tan(deg2rad(30))*xx",
            "15 - tan(degToRad()*30)*xx"
        },
        {
            "unbalanced parenthesis",
            "3.08*(1 - ((x - 300)/30)^2 - ((y - 150)/40)^2",
            "3.08*(1 - sqr((x - 300)/30) - sqr((y - 150)/40)"
        },
        {
            "unknown function",
            "sqrtt(max(25 - (x-25)^2 - (y-25)^2, 0))",
            "sqrtt(max(25 - sqr(x-25) - sqr(y-25), 0))"
        }
    };
    std::printf("\n## Error messages\n");
    for (const expressionPair& m : mistakes)
    {
        const std::string ours = errorText([&]
        {
            const scalarExpression e(m.dampm, vars, "expressionCoeffs.Z");
        });
        const std::string theirs = errorText([&]
        {
            fieldDriver driver(4);
            driver.setVariable("x", scalarField(4, 1.0));
            driver.setVariable("y", scalarField(4, 1.0));
            driver.parse(m.openfoam);
        });
        std::printf
        (
            "\n### %s\n\ndampm, `%s`:\n```\n%s\n```\n"
            "v1912, `%s`:\n```\n%s\n```\n",
            m.name, m.dampm, ours.c_str(), m.openfoam, theirs.c_str()
        );
    }

    if (!(worstDiff <= sameTol))
    {
        std::printf
        (
            "\nFAILED: the two parsers' values differ by %g > %g: an"
            " expression pair is not the same function\n", worstDiff, sameTol
        );
        return 1;
    }
    return 0;
}


// ************************************************************************* //
