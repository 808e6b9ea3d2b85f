/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "depthAveragedFields.H"
#include "particleCloudIO.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace
{
    // The names in the cloud of the fields checked on reading
    const Foam::word hName("h");
    const Foam::word AName("A");
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::depthAveragedFields::depthAveragedFields(particleArrays& particles)
{
    typedef particleArrays::fieldKind kind;
    h_ = particles.addField(hName, kind::scalar);
    A_ = particles.addField(AName, kind::scalar);
    F_ = particles.addField("F", kind::tensor2D);
    gradU_ = particles.addField("gradU", kind::tensor2D);
    sigma_ = particles.addField("sigma", kind::symmTensor);
    gradZeta_ = particles.addField("gradZeta", kind::internal, 0, 2);
    gradZ_ = particles.addField("gradZ", kind::internal, 0, 2);
    kappa_ = particles.addField("kappa", kind::internal, 1, 1);
    Zb_ = particles.addField("Zb", kind::scalar);
    basal_ = particles.addField("basal", kind::internal, 0, 3);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::depthAveragedFields::checkRead
(
    const particleArrays& particles,
    const fileName& dir
) const
{
    particleCloudIO::checkRange(particles, dir, hName, 0, true, GREAT);
    particleCloudIO::checkRange(particles, dir, AName, 0, false, GREAT);
}


Foam::runOutFields Foam::depthAveragedFields::runOut
(
    const particleArrays& particles
) const
{
    runOutFields v;
    v.n = particles.size();
    v.x = particles.component(particleArrays::X);
    v.y = particles.component(particleArrays::Y);
    v.ux = particles.component(particleArrays::UX);
    v.uy = particles.component(particleArrays::UY);
    v.m = particles.component(particleArrays::M);
    v.V = particles.component(particleArrays::VOL);
    v.A = particles.component(A_);
    for (int k = 0; k < 4; ++k)
    {
        v.F[k] = particles.component(F_ + k);
        v.gradU[k] = particles.component(gradU_ + k);
    }
    return v;
}


// ************************************************************************* //
