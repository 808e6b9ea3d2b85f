/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "yieldViscosity.H"
#include "knownKeywords.H"
#include "boundedScalar.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::yieldViscosity::regularisationType>
Foam::yieldViscosity::regularisationNames
({
    { regularisationType::Papanastasiou, "Papanastasiou" },
    { regularisationType::biViscous, "biViscous" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

double Foam::yieldViscosity::readCoeff
(
    const dictionary& dict,
    const word& key,
    const bool positive
)
{
    knownKeywords::add(dict, {key});
    return boundedScalar
    (
        dict, key, dict.get<scalar>(key),
        positive ? scalarBound::positive : scalarBound::nonNegative
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::yieldViscosity::yieldViscosity
(
    const dictionary& dict,
    const lawType law
)
:
    law_(law),
    k_(0),
    n_(1),
    tauY_(0),
    regularisation_(regularisationType::Papanastasiou),
    m_(100),
    muMax_(0)
{
    if (law_ == lawType::HerschelBulkley)
    {
        k_ = readCoeff(dict, "k", false);
        n_ = readCoeff(dict, "n", true);
    }
    else
    {
        k_ = readCoeff(dict, "mu", false);
    }
    if (law_ == lawType::Newtonian)
    {
        return;
    }

    knownKeywords::add(dict, {"regularisation", "m", "muMax"});
    tauY_ = readCoeff(dict, "tauY", false);
    regularisation_ = regularisationNames.getOrDefault
    (
        "regularisation",
        dict,
        regularisationType::Papanastasiou
    );
    if (dict.found("m"))
    {
        m_ = readCoeff(dict, "m", true);
    }
    if (regularisation_ == regularisationType::biViscous)
    {
        muMax_ = dict.get<scalar>("muMax");
        if (!(muMax_ > power(1)))
        {
            FatalIOErrorInFunction(dict)
                << "muMax = " << muMax_ << " is invalid; allowed: muMax >"
                << " the viscosity at unit shear rate " << power(1)
                << " [Pa s]" << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

double Foam::yieldViscosity::maxViscosity() const
{
    if (law_ == lawType::Newtonian)
    {
        return k_;
    }
    if (regularisation_ == regularisationType::biViscous)
    {
        return muMax_;
    }
    // The power-law part is largest at 1/m for n < 1, unbounded above for
    // n > 1 (bounded by the flow's shear rates; the caller adds them)
    return (n_ < 1 ? power(1/m_) : k_) + m_*tauY_;
}


bool Foam::yieldViscosity::sameAs
(
    const yieldViscosity& other,
    const double relTol
) const
{
    auto same = [relTol](const double a, const double b)
    {
        return std::abs(a - b) <= relTol*Foam::max(std::abs(a), std::abs(b));
    };
    if (!same(k_, other.k_) || !same(n_, other.n_))
    {
        return false;
    }
    if (!same(tauY_, other.tauY_))
    {
        return false;
    }
    if (tauY_ == 0)
    {
        return true;
    }
    return
        regularisation_ == other.regularisation_
     && same(m_, other.m_)
     && same(muMax_, other.muMax_);
}


void Foam::yieldViscosity::describe(Ostream& os) const
{
    if (law_ == lawType::HerschelBulkley)
    {
        os  << "k = " << k_ << " Pa s^n, n = " << n_;
    }
    else
    {
        os  << "mu = " << k_ << " Pa s";
    }
    if (law_ == lawType::Newtonian)
    {
        return;
    }
    os  << ", tauY = " << tauY_ << " Pa, "
        << regularisationNames[regularisation_];
    if (regularisation_ == regularisationType::biViscous)
    {
        os  << " muMax = " << muMax_ << " Pa s";
    }
    else
    {
        os  << " m = " << m_ << " s";
    }
}


// ************************************************************************* //
