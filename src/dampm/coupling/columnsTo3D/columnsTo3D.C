/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "columnsTo3D.H"
#include "particleMemory.H"
#include <cmath>
#include <unordered_map>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::columnsTo3D::profileType>
Foam::columnsTo3D::profileNames
({
    { profileType::uniform, "uniform" },
    { profileType::Bagnold, "Bagnold" },
});


const Foam::Enum<Foam::columnsTo3D::verticalType>
Foam::columnsTo3D::verticalNames
({
    { verticalType::continuity, "continuity" },
    { verticalType::bed, "bed" },
});


namespace
{

using Foam::label;

//- A column as the conversion sees it
struct column
{
    double x, y;        // centre [m]
    double a[2], b[2];  // footprint edges, scaled to the area V/h [m]
    double h;           // depth [m]
    label na, nb, nz;   // particles along a, b and the depth

    label size() const
    {
        return na*nb*nz;
    }

    //- Horizontal position of sub-footprint (i, j)
    void at(const label i, const label j, double& px, double& py) const
    {
        const double s = (i + 0.5)/na - 0.5, t = (j + 0.5)/nb - 0.5;
        px = x + s*a[0] + t*b[0];
        py = y + s*a[1] + t*b[1];
    }
};


//- Subdivisions of a length over a spacing: at least 1
Foam::label subdivisions(const double length, const double spacing)
{
    return Foam::max(Foam::label(1), Foam::label(std::lround(length/spacing)));
}


//- The edges a, b of column c's footprint, its F scaled to its area A (a
//  square of area A where F is degenerate)
void footprintEdges
(
    const Foam::runOutFields& columns,
    const Foam::label c,
    double a[2],
    double b[2]
)
{
    const double A = columns.A[c];
    const double F00 = columns.F[0][c], F01 = columns.F[1][c];
    const double F10 = columns.F[2][c], F11 = columns.F[3][c];
    const double det = std::abs(F00*F11 - F01*F10);
    if (det > 1e-12*A && A > 0)
    {
        const double s = std::sqrt(A/det);
        a[0] = s*F00;
        a[1] = s*F10;
        b[0] = s*F01;
        b[1] = s*F11;
    }
    else
    {
        const double s = std::sqrt(Foam::max(A, 0.0));
        a[0] = s; a[1] = 0;
        b[0] = 0; b[1] = s;
    }
}


//- Does column c have mass and area, and its centre within the region's
//  x-y bounds?
bool convertible
(
    const Foam::runOutFields& columns,
    const Foam::label c,
    const Foam::boundBox& region
)
{
    const double x = columns.x[c], y = columns.y[c];
    const Foam::point& lo = region.min();
    const Foam::point& hi = region.max();
    return
        columns.A[c] > 0 && columns.m[c] > 0
     && x >= lo.x() && x <= hi.x() && y >= lo.y() && y <= hi.y();
}


//- The cell of a grid of the spacing (from the region's lower corner) that
//  column c is merged in: -1 unless it lies in the region, has mass and
//  area, and is smaller than the spacing s_h along both edges
int64_t mergeCell
(
    const Foam::runOutFields& columns,
    const Foam::label c,
    const Foam::boundBox& region,
    const Foam::vector& spacing
)
{
    const double x = columns.x[c], y = columns.y[c];
    const Foam::point& lo = region.min();
    const Foam::point& hi = region.max();
    const double sh = std::sqrt(spacing.x()*spacing.y());
    double a[2], b[2];
    footprintEdges(columns, c, a, b);
    if
    (
        !convertible(columns, c, region)
     || !(std::hypot(a[0], a[1]) < sh && std::hypot(b[0], b[1]) < sh)
    )
    {
        return -1;
    }
    // (Clamped: a centre on the upper side is in the last cell)
    const int64_t nbx = std::max
    (
        int64_t(1), int64_t(std::ceil((hi.x() - lo.x())/spacing.x()))
    );
    const int64_t nby = std::max
    (
        int64_t(1), int64_t(std::ceil((hi.y() - lo.y())/spacing.y()))
    );
    const int64_t ix = std::min(int64_t((x - lo.x())/spacing.x()), nbx - 1);
    const int64_t iy = std::min(int64_t((y - lo.y())/spacing.y()), nby - 1);
    return ix + nbx*iy;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::columnsTo3D::profileFactors
(
    const label nz,
    std::vector<scalar>& f
) const
{
    f.assign(nz, 1.0);
    if (profile_ == profileType::uniform || nz == 1)
    {
        return;
    }
    // Bagnold (dense granular flow): u ~ 1 - (1 - z/h)^(3/2), scaled so that
    // the level average is exactly the column's velocity
    scalar sum = 0;
    for (label k = 0; k < nz; ++k)
    {
        const scalar zeta = (k + 0.5)/nz;
        f[k] = 1 - std::pow(1 - zeta, 1.5);
        sum += f[k];
    }
    for (scalar& fk : f)
    {
        fk *= nz/sum;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::columnsTo3D::columnsTo3D
(
    const boundBox& region,
    const vector& spacing,
    const materialModel& material,
    const scalar g,
    const profileType profile,
    const groundFunction& ground,
    const verticalType vertical
)
:
    region_(region),
    spacing_(spacing),
    material_(material),
    g_(g),
    profile_(profile),
    vertical_(vertical),
    ground_(ground)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::columnsTo3D::totals Foam::columnsTo3D::convert
(
    const runOutFields& columns,
    particleArrays& particles3D,
    const mpm3dFlow::stressFields& stress3D,
    std::vector<char>* inRegion
) const
{
    const label nCol = columns.n;
    const double* cx = columns.x;
    const double* cy = columns.y;
    const double* cu = columns.ux;
    const double* cv = columns.uy;
    const double* cm = columns.m;
    const double* cV = columns.V;
    const double* cA = columns.A;

    // The divergence of the column's velocity (trace of gradU): the layer's
    // thinning rate over its depth
    const bool continuity =
        vertical_ == verticalType::continuity && columns.gradU[0] != nullptr;
    const double* Cxx = continuity ? columns.gradU[0] : nullptr;
    const double* Cyy = continuity ? columns.gradU[3] : nullptr;

    const scalar sh = std::sqrt(spacing_.x()*spacing_.y());
    const point& lo = region_.min();
    const point& hi = region_.max();

    // A hair inside the x-y bounds
    const double eps = 1e-9*sh;
    auto clampInside = [&](double& px, double& py)
    {
        px = Foam::min(Foam::max(px, lo.x() + eps), hi.x() - eps);
        py = Foam::min(Foam::max(py, lo.y() + eps), hi.y() - eps);
    };

    // Pass 1: the geometry of every column, and which convert
    totals t;
    std::vector<column> geo(nCol);
    std::vector<char> converted(nCol, 0);
    double nParticles = 0;
    for (label c = 0; c < nCol; ++c)
    {
        column& col = geo[c];
        col.x = cx[c];
        col.y = cy[c];
        const double A = cA[c];
        col.h = A > 0 ? cV[c]/A : 0;

        // The footprint's shape with the column's area
        footprintEdges(columns, c, col.a, col.b);
        col.na = subdivisions(std::hypot(col.a[0], col.a[1]), sh);
        col.nb = subdivisions(std::hypot(col.b[0], col.b[1]), sh);
        col.nz = subdivisions(col.h, spacing_.z());

        // Inside: the centre within the region's x-y bounds (the particles
        // are kept inside them, at most half a footprint away), the column
        // between the region's bottom and top
        bool inside = convertible(columns, c, region_);
        if (inside)
        {
            double zBed = GREAT, zTop = -GREAT;
            for (int corner = 0; corner < 4; ++corner)
            {
                double px, py;
                col.at(corner & 1 ? col.na - 1 : 0, corner & 2 ? col.nb - 1 : 0,
                    px, py);
                clampInside(px, py);
                vector2D gradG;
                const double G = ground_(px, py, gradG);
                zBed = Foam::min(zBed, G);
                zTop = Foam::max(zTop, G + col.h);
            }
            if (zTop > hi.z() || zBed < lo.z())
            {
                inside = false;
                ++t.columnsAbove;
            }
        }
        converted[c] = inside;
        nParticles += inside ? double(col.na)*col.nb*col.nz : 0;
        if (!inside)
        {
            ++t.unconvertedColumns;
            t.unconvertedMass += cm[c];
        }
    }

    particleMemory::reserve
    (
        particles3D, nParticles, "the conversion of " + std::to_string(nCol)
      + " columns at the 3D particle spacing (particlesPerCell of"
        " constant/mpm3dProperties and the 3D mesh)"
    );

    // Pass 2: the particles
    const label sigma = stress3D.sigma;
    const label pField = stress3D.p;
    const label JField = stress3D.J;
    const scalar rho0 = material_.rho();

    std::vector<scalar> f;
    for (label c = 0; c < nCol; ++c)
    {
        if (!converted[c])
        {
            continue;
        }
        const column& col = geo[c];
        const label n = col.size();
        const scalar mp = cm[c]/n;
        const scalar V0p = cV[c]/n;
        const scalar divU = continuity ? Cxx[c] + Cyy[c] : 0;
        profileFactors(col.nz, f);

        const label first = particles3D.append(n);
        scalar mSum = 0, VSum = 0;
        label i = first;
        for (label k = 0; k < col.nz; ++k)
        {
            const scalar zeta = (k + 0.5)/col.nz;
            const scalar p = rho0*g_*col.h*(1 - zeta);
            const scalar J = material_.restJ(p);
            for (label jb = 0; jb < col.nb; ++jb)
            {
                for (label ia = 0; ia < col.na; ++ia, ++i)
                {
                    double px, py;
                    col.at(ia, jb, px, py);
                    clampInside(px, py);
                    vector2D gradG;
                    const scalar G = ground_(px, py, gradG);
                    const scalar u = f[k]*cu[c], v = f[k]*cv[c];
                    const scalar wBed = u*gradG.x() + v*gradG.y();
                    const scalar w = wBed - zeta*col.h*divU;

                    particles3D.component(particleArrays::X)[i] = px;
                    particles3D.component(particleArrays::Y)[i] = py;
                    particles3D.component(particleArrays::Z)[i] = G + zeta*col.h;
                    particles3D.component(particleArrays::UX)[i] = u;
                    particles3D.component(particleArrays::UY)[i] = v;
                    particles3D.component(particleArrays::UZ)[i] = w;
                    particles3D.component(particleArrays::M)[i] = mp;
                    particles3D.component(particleArrays::VOL)[i] = J*V0p;
                    particles3D.component(pField)[i] = p;
                    particles3D.component(JField)[i] = J;
                    // xx, yy, zz of the symmetric tensor
                    particles3D.component(sigma)[i] = -p;
                    particles3D.component(sigma + 3)[i] = -p;
                    particles3D.component(sigma + 5)[i] = -p;

                    mSum += mp;
                    VSum += V0p;
                    t.volume3DCurrent += J*V0p;
                    t.momentum3D[0] += mp*u;
                    t.momentum3D[1] += mp*v;
                    t.kineticEnergy3D += 0.5*mp*(u*u + v*v);
                    t.kineticEnergyVertical += 0.5*mp*w*w;
                    t.kineticEnergyBed += 0.5*mp*wBed*wBed;
                }
            }
        }

        ++t.columns;
        t.particles += n;
        t.massDA += cm[c];
        t.mass3D += mSum;
        t.volumeDA += cV[c];
        t.volume3D += VSum;
        t.momentumDA[0] += cm[c]*cu[c];
        t.momentumDA[1] += cm[c]*cv[c];
        t.kineticEnergyDA += 0.5*cm[c]*(cu[c]*cu[c] + cv[c]*cv[c]);
        t.maxColumnMassError =
            Foam::max(t.maxColumnMassError, std::abs(mSum - cm[c])/cm[c]);
        t.maxColumnVolumeError =
            Foam::max(t.maxColumnVolumeError, std::abs(VSum - cV[c])/cV[c]);
    }

    if (inRegion)
    {
        *inRegion = std::move(converted);
    }
    return t;
}


Foam::columnsTo3D::mergedColumns Foam::columnsTo3D::merge
(
    const runOutFields& columns
) const
{
    typedef mergedColumns mc;
    const bool withGradU = columns.gradU[0] != nullptr;
    const int nFields = withGradU ? mc::nAll : mc::G0;
    const double* const source[mc::nAll] =
    {
        columns.x, columns.y, columns.ux, columns.uy, columns.m, columns.V,
        columns.A, columns.F[0], columns.F[1], columns.F[2], columns.F[3],
        columns.gradU[0], columns.gradU[1], columns.gradU[2], columns.gradU[3]
    };

    const label nCol = columns.n;
    mergedColumns merged;
    std::vector<std::vector<double>>& out = merged.fields_;
    out.assign(nFields, std::vector<double>());
    merged.into.resize(nCol);
    std::vector<label> firstSource, nSources;
    std::unordered_map<int64_t, label> columnOfCell;

    // Sums in source order: the mass-weighted ones as m x, m u, m gradU
    for (label c = 0; c < nCol; ++c)
    {
        const double m = columns.m[c];
        const int64_t cell = mergeCell(columns, c, region_, spacing_);
        label k = label(firstSource.size());
        if (cell >= 0)
        {
            k = columnOfCell.emplace(cell, k).first->second;
        }
        if (k == label(firstSource.size()))
        {
            firstSource.push_back(c);
            nSources.push_back(0);
            for (std::vector<double>& f : out)
            {
                f.push_back(0);
            }
        }
        merged.into[c] = k;
        ++nSources[k];
        for (const int f : {mc::X, mc::Y, mc::UX, mc::UY})
        {
            out[f][k] += m*source[f][c];
        }
        for (const int f : {mc::M, mc::V, mc::A})
        {
            out[f][k] += source[f][c];
        }
        for (int f = mc::G0; f < nFields; ++f)
        {
            out[f][k] += m*source[f][c];
        }
        merged.kineticEnergySource +=
            0.5*m*(sqr(columns.ux[c]) + sqr(columns.uy[c]));
    }

    // A column alone in its cell, or not merged, exactly as it was; the
    // merged ones their means and a square footprint
    for (size_t k = 0; k < firstSource.size(); ++k)
    {
        if (nSources[k] == 1)
        {
            for (int f = 0; f < nFields; ++f)
            {
                out[f][k] = source[f][firstSource[k]];
            }
        }
        else
        {
            const double m = out[mc::M][k];
            for (const int f : {mc::X, mc::Y, mc::UX, mc::UY})
            {
                out[f][k] /= m;
            }
            for (int f = mc::G0; f < nFields; ++f)
            {
                out[f][k] /= m;
            }
            out[mc::F0][k] = out[mc::F0 + 3][k] = 1;
            out[mc::F0 + 1][k] = out[mc::F0 + 2][k] = 0;
            ++merged.nMerged;
            merged.nMergedSource += nSources[k];
        }
        merged.kineticEnergy +=
            0.5*out[mc::M][k]*(sqr(out[mc::UX][k]) + sqr(out[mc::UY][k]));
    }
    return merged;
}


Foam::runOutFields Foam::columnsTo3D::mergedColumns::view() const
{
    runOutFields v;
    const std::vector<std::vector<double>>& f = fields_;
    v.n = label(f[X].size());
    v.x = f[X].data();
    v.y = f[Y].data();
    v.ux = f[UX].data();
    v.uy = f[UY].data();
    v.m = f[M].data();
    v.V = f[V].data();
    v.A = f[A].data();
    for (int k = 0; k < 4; ++k)
    {
        v.F[k] = f[F0 + k].data();
        v.gradU[k] = f.size() > G0 ? f[G0 + k].data() : nullptr;
    }
    return v;
}


std::vector<char> Foam::columnsTo3D::mergedColumns::perSource
(
    const std::vector<char>& merged
) const
{
    std::vector<char> flags(into.size());
    for (size_t c = 0; c < into.size(); ++c)
    {
        flags[c] = merged[into[c]];
    }
    return flags;
}


void Foam::columnsTo3D::mergedColumns::report(Ostream& os) const
{
    os  << "Merged " << nMergedSource << " of " << into.size()
        << " columns, smaller than the 3D particle spacing, into "
        << nMerged << " (one per cell of the spacing): "
        << fields_[0].size() << " columns to convert" << nl
        << "    kinetic energy of the horizontal motion " << kineticEnergySource
        << " J before, " << kineticEnergy << " J after (relative change "
        << (kineticEnergy - kineticEnergySource)
          /Foam::max(kineticEnergySource, VSMALL)
        << ": the velocity differences within a cell)" << nl;
}


void Foam::columnsTo3D::report(const totals& t, Ostream& os)
{
    auto rel = [](const scalar a, const scalar b)
    {
        return std::abs(a - b)/Foam::max(std::abs(b), VSMALL);
    };
    os  << "Converted " << t.columns << " columns into " << t.particles
        << " 3D particles" << nl
        << "    mass        DA " << t.massDA << " kg, 3D " << t.mass3D
        << " kg (relative error " << rel(t.mass3D, t.massDA)
        << ", largest of a column " << t.maxColumnMassError << ")" << nl
        << "    volume      DA " << t.volumeDA << " m^3, 3D " << t.volume3D
        << " m^3 at the reference density (relative error "
        << rel(t.volume3D, t.volumeDA) << ", largest of a column "
        << t.maxColumnVolumeError << "); under the hydrostatic load "
        << t.volume3DCurrent << " m^3" << nl
        << "    momentum    DA (" << t.momentumDA[0] << ' ' << t.momentumDA[1]
        << ") kg m/s, 3D (" << t.momentum3D[0] << ' ' << t.momentum3D[1]
        << ")" << nl
        << "    kinetic energy of the horizontal motion DA "
        << t.kineticEnergyDA << " J, 3D " << t.kineticEnergy3D
        << " J (relative difference "
        << rel(t.kineticEnergy3D, t.kineticEnergyDA) << ")" << nl
        << "    kinetic energy of the added vertical motion "
        << t.kineticEnergyVertical << " J (along the bed alone "
        << t.kineticEnergyBed << " J)" << nl
        << "    not converted: " << t.unconvertedColumns << " columns, "
        << t.unconvertedMass << " kg (outside the 3D region";
    if (t.columnsAbove)
    {
        os  << "; " << t.columnsAbove << " of them inside it but reaching"
            << " above its top or below its bottom";
    }
    os  << ")" << nl;
}


// ************************************************************************* //
