/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "materialModel.H"
#include "knownKeywords.H"
#include "modelConstructor.H"
#include "fpTrapsHeld.H"
#include "OStringStream.H"
#include <cmath>

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::materialModel> Foam::materialModel::New
(
    const dictionary& dict
)
{
    const word modelType(dict.get<word>("material"));
    knownKeywords::addSelector
    (
        dict, "material", dictionaryConstructorTablePtr_->sortedToc()
    );
    const dictionary& coeffs = dict.optionalSubDict(modelType + "Coeffs");

    autoPtr<materialModel> model
    (
        modelConstructor<materialModel>(dict, "material", modelType)(coeffs)
    );

    // The derived values the time step takes, computed with the traps
    // held: coefficients within their ranges may still combine to one
    // that is not finite (mu + m tauY of a regularised yield stress)
    scalar c = 0, mu = 0;
    bool finite = false;
    {
        const fpTrapsHeld hold;
        c = model->waveSpeed();
        mu = model->explicitViscosity();
        finite = std::isfinite(c) && c > 0 && std::isfinite(mu) && mu >= 0;
    }
    if (!finite)
    {
        OStringStream described;
        model->describe(described);
        FatalIOErrorInFunction(coeffs)
            << "the coefficients of " << described.str().c_str() << " give"
            << " a wave speed of " << c << " m/s and a viscosity of " << mu
            << " Pa s for the explicit time step; allowed: coefficients"
            << " whose wave speed is finite and positive and whose largest"
            << " viscosity is finite" << exit(FatalIOError);
    }
    return model;
}


// ************************************************************************* //
