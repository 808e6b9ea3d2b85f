/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "barrierGeometry.H"
#include "knownKeywords.H"
#include "modelConstructor.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::barrierGeometry> Foam::barrierGeometry::New
(
    const word& name,
    const dictionary& dict,
    const fileName& caseDir
)
{
    const word modelType(dict.get<word>("type"));
    knownKeywords::add(dict, {"type"});

    return autoPtr<barrierGeometry>
    (
        modelConstructor<barrierGeometry>(dict, "type", modelType)
        (name, dict, caseDir)
    );
}


// ************************************************************************* //
