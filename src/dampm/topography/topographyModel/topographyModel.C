/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "topographyModel.H"
#include "knownKeywords.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(topographyModel, 0);
    defineRunTimeSelectionTable(topographyModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::topographyModel::topographyModel
(
    const dictionary& coeffs,
    const fileName& caseDir
)
:
    coeffs_(coeffs),
    caseDir_(caseDir)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::topographyModel::sampleNodes
(
    const gridGeometry& g,
    double* Znodes
) const
{
    for (label j = 0; j < g.nNodesDir[1]; ++j)
    {
        for (label i = 0; i < g.nNodesDir[0]; ++i)
        {
            const label ig = i - gridGeometry::nGhost;
            const label jg = j - gridGeometry::nGhost;
            Znodes[i + j*g.nodeStride[1]] =
                Z(g.nodeCoord(0, ig), g.nodeCoord(1, jg));
        }
    }
}


Foam::fileName Foam::topographyModel::caseFile(const word& key) const
{
    knownKeywords::add(coeffs_, {key});
    fileName file(coeffs_.get<fileName>(key));
    file.expand();
    return file.isAbsolute() ? file : caseDir_/file;
}


// ************************************************************************* //
