/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "barrierModel.H"
#include "knownKeywords.H"
#include "modelConstructor.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::barrierModel> Foam::barrierModel::New
(
    const word& name,
    const dictionary& dict,
    const fileName& caseDir
)
{
    const word modelType(dict.get<word>("type"));
    knownKeywords::add(dict, {"type"});

    return autoPtr<barrierModel>
    (
        modelConstructor<barrierModel>(dict, "type", modelType)
        (name, dict, caseDir)
    );
}


// ************************************************************************* //
