/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "standardNormal.H"
#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- Acklam's approximation of the quantile (relative error 1.15e-9)
double acklamQuantile(const double p)
{
    static const double a[6] =
    {
        -3.969683028665376e+01, 2.209460984245205e+02,
        -2.759285104469687e+02, 1.383577518672690e+02,
        -3.066479806614716e+01, 2.506628277459239e+00
    };
    static const double b[5] =
    {
        -5.447609879822406e+01, 1.615858368580409e+02,
        -1.556989798598866e+02, 6.680131188771972e+01,
        -1.328068155288572e+01
    };
    static const double c[6] =
    {
        -7.784894002430293e-03, -3.223964580411365e-01,
        -2.400758277161838e+00, -2.549732539343734e+00,
        4.374664141464968e+00, 2.938163982698783e+00
    };
    static const double d[4] =
    {
        7.784695709041462e-03, 3.224671290700398e-01,
        2.445134137142996e+00, 3.754408661907416e+00
    };

    // The tails' rational function in q = sqrt(-2 ln(tail probability))
    const auto tail = [&](const double q)
    {
        return
            (((((c[0]*q + c[1])*q + c[2])*q + c[3])*q + c[4])*q + c[5])
           /((((d[0]*q + d[1])*q + d[2])*q + d[3])*q + 1);
    };

    constexpr double pLow = 0.02425;
    if (p < pLow)
    {
        return tail(std::sqrt(-2*std::log(p)));
    }
    if (p > 1 - pLow)
    {
        return -tail(std::sqrt(-2*std::log1p(-p)));
    }
    const double q = p - 0.5;
    const double r = q*q;
    return
        (((((a[0]*r + a[1])*r + a[2])*r + a[3])*r + a[4])*r + a[5])*q
       /(((((b[0]*r + b[1])*r + b[2])*r + b[3])*r + b[4])*r + 1);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::standardNormal::cdf(const scalar z)
{
    return 0.5*std::erfc(-z/std::sqrt(2.0));
}


Foam::scalar Foam::standardNormal::complementaryCdf(const scalar z)
{
    return 0.5*std::erfc(z/std::sqrt(2.0));
}


Foam::scalar Foam::standardNormal::quantile(const scalar p)
{
    const double z = acklamQuantile(p);

    // One Halley step on the residual of the CDF: third order, so the
    // approximation's 1e-9 becomes round-off
    const double e = cdf(z) - p;
    const double u = e*std::sqrt(2*M_PI)*std::exp(0.5*z*z);
    return z - u/(1 + 0.5*z*u);
}


Foam::scalar Foam::standardNormal::truncatedQuantile
(
    const scalar u,
    const scalar zLo,
    const scalar zHi
)
{
    double z;
    if (zLo > 0)
    {
        const double qLo = complementaryCdf(zLo);
        const double qHi = complementaryCdf(zHi);
        z = -quantile(qLo - u*(qLo - qHi));
    }
    else
    {
        const double pLo = cdf(zLo);
        const double pHi = cdf(zHi);
        z = quantile(pLo + u*(pHi - pLo));
    }
    // Round-off at a bound stays inside it
    return std::min(std::max(z, zLo), zHi);
}


Foam::scalar Foam::standardNormal::probability
(
    const scalar zLo,
    const scalar zHi
)
{
    return
        zLo > 0
      ? complementaryCdf(zLo) - complementaryCdf(zHi)
      : cdf(zHi) - cdf(zLo);
}


// ************************************************************************* //
