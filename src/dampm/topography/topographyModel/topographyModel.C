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
#include "fpTrapsHeld.H"
#include "OStringStream.H"
#include "IOmanip.H"
#include <cmath>

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
    caseDir_(caseDir),
    byDefault_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::topographyModel::sampleNodes
(
    const gridGeometry& g,
    double* Znodes
) const
{
    checkCovers(g);

    // Traps masked for the whole loop, not per node: what is not finite
    // (or too large to compute with) is found here and refused by its node
    const gridGeometry::index nG = gridGeometry::nGhost;
    label bad = -1, badSlope = -1;
    vector2D slope(Zero);
    {
        fpTrapsHeld masked;
        for (label j = 0; j < g.nNodesDir[1]; ++j)
        {
            for (label i = 0; i < g.nNodesDir[0]; ++i)
            {
                const label nodei = i + j*g.nodeStride[1];
                const scalar x = g.nodeCoord(0, i - nG);
                const scalar y = g.nodeCoord(1, j - nG);
                const scalar z = Z(x, y);
                Znodes[nodei] = z;
                if (bad < 0 && !(std::isfinite(z) && std::abs(z) <= maxAbsZ))
                {
                    bad = nodei;
                }
                const vector2D grad = gradient(x, y);
                if
                (
                    badSlope < 0
                 && !(std::isfinite(grad.x()) && std::isfinite(grad.y()))
                )
                {
                    badSlope = nodei;
                    slope = grad;
                }
            }
        }
    }

    const auto at = [&](const label nodei)
    {
        const label i = nodei % g.nodeStride[1] - nG;
        const label j = nodei/g.nodeStride[1] - nG;
        const label iD = i + g.offset[0];
        const label jD = j + g.offset[1];
        const bool ghost =
            iD < 0 || jD < 0 || iD > g.nCellsDomain[0]
         || jD > g.nCellsDomain[1];
        return
            "(x y) = (" + Foam::name(g.nodeCoord(0, i)) + ' '
          + Foam::name(g.nodeCoord(1, j)) + ')'
          + (ghost ? " (a ghost node, one cell outside the mesh)" : "");
    };

    if (bad >= 0)
    {
        FatalIOErrorInFunction(coeffs_)
            << setprecision(12)
            << "the topography " << description().c_str() << " gives Z = "
            << Znodes[bad] << " m at the grid node " << at(bad).c_str()
            << "; allowed: a finite Z with |Z| <= " << maxAbsZ << " m at"
            << " every node of the grid, the ghost nodes one cell outside the"
            << " mesh included"
            << exit(FatalIOError);
    }
    if (badSlope >= 0)
    {
        FatalIOErrorInFunction(coeffs_)
            << setprecision(12)
            << "the topography " << description().c_str() << " has the"
            << " gradient " << slope << " at the grid node "
            << at(badSlope).c_str() << "; allowed: a finite gradient at every"
            << " node of the grid, the ghost nodes one cell outside the mesh"
            << " included"
            << exit(FatalIOError);
    }

    if (g.dim != 2)
    {
        return;
    }

    // The 2D mesh's one cell in z holds the columns' free surfaces: the
    // bed must lie in it (the rounding of a raster's bilinear sum allowed)
    label lowest, highest;
    meshRange(g, Znodes, lowest, highest);
    const scalar zLo = g.origin[2];
    const scalar zHi = g.upper(2);
    const scalar tol = 1e-12*max(max(mag(zLo), mag(zHi)), scalar(1));
    if (Znodes[lowest] < zLo - tol || Znodes[highest] > zHi + tol)
    {
        FatalIOErrorInFunction(coeffs_)
            << setprecision(12)
            << "the terrain, topography " << description().c_str()
            << (byDefault_ ? " (the default: no keyword topography)" : "")
            << ", ranges from Z = " << Znodes[lowest] << " m at "
            << at(lowest).c_str() << " to Z = " << Znodes[highest]
            << " m at " << at(highest).c_str() << " over the mesh's nodes,"
            << " outside the mesh's z-range " << zLo << " to " << zHi
            << " m (the vertices of system/blockMeshDict); allowed: " << zLo
            << " <= Z <= " << zHi << " m at every node of the mesh. The"
            << " columns are written at their free surface z = Z + h, which"
            << " must lie in the one-cell-thick mesh: let its z-range reach"
            << " from the lowest terrain to above the highest free surface"
            << exit(FatalIOError);
    }
}


void Foam::topographyModel::meshRange
(
    const gridGeometry& g,
    const double* Znodes,
    label& lowest,
    label& highest
)
{
    const gridGeometry::index nG = gridGeometry::nGhost;
    lowest = highest = nG*(1 + g.nodeStride[1]);
    for (label j = nG; j <= nG + g.nCells[1]; ++j)
    {
        for (label i = nG; i <= nG + g.nCells[0]; ++i)
        {
            const label nodei = i + j*g.nodeStride[1];
            lowest = Znodes[nodei] < Znodes[lowest] ? nodei : lowest;
            highest = Znodes[nodei] > Znodes[highest] ? nodei : highest;
        }
    }
}


Foam::string Foam::topographyModel::description() const
{
    OStringStream os;
    describe(os);
    return os.str();
}


Foam::fileName Foam::topographyModel::caseFile(const word& key) const
{
    knownKeywords::add(coeffs_, {key});
    fileName file(coeffs_.get<fileName>(key));
    file.expand();
    return file.isAbsolute() ? file : caseDir_/file;
}


// ************************************************************************* //
