/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "membraneElements.H"
#include "structureInput.H"
#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

inline void Foam::membraneElements::deformationGradient
(
    const label* n,
    const double* g,
    const double* x,
    const double* y,
    const double* z,
    double a[3],
    double b[3]
)
{
    for (label c = 0; c < 3; ++c)
    {
        a[c] = b[c] = 0;
    }
    for (label i = 0; i < 3; ++i)
    {
        const double p[3] = {x[n[i]], y[n[i]], z[n[i]]};
        for (label c = 0; c < 3; ++c)
        {
            a[c] += p[c]*g[2*i];
            b[c] += p[c]*g[2*i + 1];
        }
    }
}


inline void Foam::membraneElements::planeStress
(
    const double D,
    const double nu,
    const double E11,
    const double E22,
    const double E12,
    double& S11,
    double& S22,
    double& S12
)
{
    S11 = D*(E11 + nu*E22);
    S22 = D*(E22 + nu*E11);
    S12 = D*(1 - nu)*E12;
}


void Foam::membraneElements::readMaterial(const dictionary& dict)
{
    h_ = structureInput::positive(dict, "thickness", "[m]");
    E_ = structureInput::positive(dict, "E", "[Pa]");
    nu_ = dict.get<scalar>("nu");
    // nu = 0.5 makes the plane-stress modulus E/(1 - nu^2) finite but the
    // membrane incompressible, which a CST locks on
    if (!(nu_ > -1 && nu_ < 0.5))
    {
        FatalIOErrorInFunction(dict)
            << "nu = " << nu_ << " is invalid; allowed: -1 < nu < 0.5"
            << exit(FatalIOError);
    }
    rho_ = structureInput::positive(dict, "rho", "[kg/m^3]");
    // No bending stiffness: a compressive prestress buckles at once
    S0_ = structureInput::nonNegative(dict, "prestress", 0, "[Pa]");
}


void Foam::membraneElements::setReferenceGeometry
(
    const label trii,
    const structureNodes& nodes,
    const dictionary& dict
)
{
    const point X1 = nodes.referencePosition(node_[3*trii]);
    const point X2 = nodes.referencePosition(node_[3*trii + 1]);
    const point X3 = nodes.referencePosition(node_[3*trii + 2]);

    const vector n = (X2 - X1) ^ (X3 - X1);
    const scalar area = 0.5*mag(n);
    const scalar longest =
        max(mag(X2 - X1), max(mag(X3 - X2), mag(X1 - X3)));
    if (!(area > 1e-12*sqr(longest)))
    {
        FatalIOErrorInFunction(dict)
            << "Triangle " << trii << " of the membrane, " << X1 << ' '
            << X2 << ' ' << X3 << ", has no area" << exit(FatalIOError);
    }

    // Local frame: e1 along the first edge, e2 in the plane
    const vector e1 = (X2 - X1)/mag(X2 - X1);
    const vector e2 = (n/mag(n)) ^ e1;
    const scalar xl[3] = {0, (X2 - X1) & e1, (X3 - X1) & e1};
    const scalar yl[3] = {0, 0, (X3 - X1) & e2};
    const scalar twoA = 2*area;

    double* g = &grad_[6*trii];
    for (label i = 0; i < 3; ++i)
    {
        const label j = (i + 1) % 3;
        const label k = (i + 2) % 3;
        g[2*i] = (yl[j] - yl[k])/twoA;
        g[2*i + 1] = (xl[k] - xl[j])/twoA;
    }
    volume_[trii] = area*h_;
    altitude_[trii] = twoA/longest;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::membraneElements::membraneElements()
:
    h_(0),
    E_(0),
    nu_(0),
    rho_(0),
    S0_(0)
{}


Foam::membraneElements::membraneElements
(
    const dictionary& dict,
    const std::vector<label>& triangles,
    structureNodes& nodes
)
:
    membraneElements()
{
    readMaterial(dict);

    node_ = triangles;
    const label nTri = label(node_.size()/3);
    volume_.resize(nTri);
    grad_.resize(6*nTri);
    altitude_.resize(nTri);
    slotForce_.assign(9*nTri, 0.0);

    for (label trii = 0; trii < nTri; ++trii)
    {
        setReferenceGeometry(trii, nodes, dict);
        for (label i = 0; i < 3; ++i)
        {
            nodes.mass[node_[3*trii + i]] += rho_*volume_[trii]/3;
        }
    }
    incidence_ = nodeIncidence(node_, nodes.size());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

double Foam::membraneElements::addInternalForces
(
    structureNodes& nodes,
    const double beta,
    double& dampingPower
)
{
    const label nTri = size();
    const double D = E_/(1 - nu_*nu_);
    const double nu = nu_;
    const double S0 = S0_;
    const double* x = nodes.x.data();
    const double* y = nodes.y.data();
    const double* z = nodes.z.data();
    const double* vx = nodes.vx.data();
    const double* vy = nodes.vy.data();
    const double* vz = nodes.vz.data();
    const label* tri = node_.data();
    const double* grad = grad_.data();
    const double* volume = volume_.data();
    double* force = slotForce_.data();

    double energy = 0;
    double power = 0;

    #pragma omp parallel for schedule(static) reduction(+:energy, power)
    for (label trii = 0; trii < nTri; ++trii)
    {
        const label* n = &tri[3*trii];
        const double* g = &grad[6*trii];

        // Columns a, b of F and ad, bd of dF/dt
        double a[3], b[3], ad[3], bd[3];
        deformationGradient(n, g, x, y, z, a, b);
        deformationGradient(n, g, vx, vy, vz, ad, bd);
        const double aa = a[0]*a[0] + a[1]*a[1] + a[2]*a[2];
        const double bb = b[0]*b[0] + b[1]*b[1] + b[2]*b[2];
        const double ab = a[0]*b[0] + a[1]*b[1] + a[2]*b[2];
        const double E11 = 0.5*(aa - 1);
        const double E22 = 0.5*(bb - 1);
        const double E12 = 0.5*ab;

        const double Ed11 = a[0]*ad[0] + a[1]*ad[1] + a[2]*ad[2];
        const double Ed22 = b[0]*bd[0] + b[1]*bd[1] + b[2]*bd[2];
        const double Ed12 = 0.5
           *(
                a[0]*bd[0] + a[1]*bd[1] + a[2]*bd[2]
              + ad[0]*b[0] + ad[1]*b[1] + ad[2]*b[2]
            );

        // Elastic and viscous 2nd Piola-Kirchhoff stresses (plane stress)
        double Se11, Se22, Se12, Sv11, Sv22, Sv12;
        planeStress(D, nu, E11, E22, E12, Se11, Se22, Se12);
        planeStress(beta*D, nu, Ed11, Ed22, Ed12, Sv11, Sv22, Sv12);
        const double S11 = S0 + Se11 + Sv11;
        const double S22 = S0 + Se22 + Sv22;
        const double S12 = Se12 + Sv12;

        const double V = volume[trii];
        energy += V
           *(
                S0*(E11 + E22)
              + 0.5*(Se11*E11 + Se22*E22 + 2*Se12*E12)
            );
        power += V*(Sv11*Ed11 + Sv22*Ed22 + 2*Sv12*Ed12);

        // f_i = -V F S g_i
        double* f = &force[9*trii];
        for (label i = 0; i < 3; ++i)
        {
            const double sa = S11*g[2*i] + S12*g[2*i + 1];
            const double sb = S12*g[2*i] + S22*g[2*i + 1];
            for (label c = 0; c < 3; ++c)
            {
                f[3*i + c] = -V*(a[c]*sa + b[c]*sb);
            }
        }
    }

    incidence_.gatherAdd(slotForce_, nodes.fx, nodes.fy, nodes.fz);
    dampingPower = power;
    return energy;
}


double Foam::membraneElements::stableTimeStep(label& trii) const
{
    const double c = std::sqrt((E_/(1 - nu_*nu_) + S0_)/rho_);
    trii = -1;
    double dt = GREAT;
    for (label elemi = 0; elemi < size(); ++elemi)
    {
        if (altitude_[elemi]/c < dt)
        {
            dt = altitude_[elemi]/c;
            trii = elemi;
        }
    }
    return dt;
}


std::vector<double> Foam::membraneElements::nodeAreas
(
    const label nNodes
) const
{
    std::vector<double> area(nNodes, 0.0);
    for (label trii = 0; trii < size(); ++trii)
    {
        for (label i = 0; i < 3; ++i)
        {
            area[node_[3*trii + i]] += volume_[trii]/h_/3;
        }
    }
    return area;
}


Foam::symmTensorField Foam::membraneElements::cauchyStress
(
    const structureNodes& nodes
) const
{
    const double D = E_/(1 - nu_*nu_);
    symmTensorField sigma(size());
    forAll(sigma, trii)
    {
        double a[3], b[3];
        deformationGradient
        (
            &node_[3*trii], &grad_[6*trii],
            nodes.x.data(), nodes.y.data(), nodes.z.data(), a, b
        );
        const vector va(a[0], a[1], a[2]);
        const vector vb(b[0], b[1], b[2]);
        const scalar E11 = 0.5*(magSqr(va) - 1);
        const scalar E22 = 0.5*(magSqr(vb) - 1);
        const scalar E12 = 0.5*(va & vb);
        double S11, S22, S12;
        planeStress(D, nu_, E11, E22, E12, S11, S22, S12);

        const scalar lambda3Sqr = 1 - 2*nu_/(1 - nu_)*(E11 + E22);
        const scalar J = mag(va ^ vb)*std::sqrt(max(lambda3Sqr, 0.01));
        sigma[trii] =
        (
            (S0_ + S11)*sqr(va) + (S0_ + S22)*sqr(vb)
          + S12*twoSymm(va*vb)
        )/J;
    }
    return sigma;
}


// ************************************************************************* //
