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
    const double* F00 = columns.F[0];
    const double* F01 = columns.F[1];
    const double* F10 = columns.F[2];
    const double* F11 = columns.F[3];

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
        const double det = std::abs(F00[c]*F11[c] - F01[c]*F10[c]);
        if (det > 1e-12*A && A > 0)
        {
            const double s = std::sqrt(A/det);
            col.a[0] = s*F00[c];
            col.a[1] = s*F10[c];
            col.b[0] = s*F01[c];
            col.b[1] = s*F11[c];
        }
        else
        {
            const double s = std::sqrt(Foam::max(A, 0.0));
            col.a[0] = s; col.a[1] = 0;
            col.b[0] = 0; col.b[1] = s;
        }
        col.na = subdivisions(std::hypot(col.a[0], col.a[1]), sh);
        col.nb = subdivisions(std::hypot(col.b[0], col.b[1]), sh);
        col.nz = subdivisions(col.h, spacing_.z());

        // Inside: the centre within the region's x-y bounds (the particles
        // are kept inside them, at most half a footprint away), the column
        // between the region's bottom and top
        bool inside =
            A > 0 && cm[c] > 0
         && col.x >= lo.x() && col.x <= hi.x()
         && col.y >= lo.y() && col.y <= hi.y();
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
