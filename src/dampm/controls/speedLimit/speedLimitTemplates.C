/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "fpTrapsHeld.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class VectorType>
VectorType Foam::speedLimit::readVelocity
(
    const dictionary& dict,
    const VectorType& deflt
)
{
    const VectorType U = dict.getOrDefault<VectorType>("U", deflt);
    bool allowed = false;
    {
        // Compared under the hold too: NaN raises a trap in a comparison
        const fpTrapsHeld hold;
        allowed = mag(U) <= maximum;
    }
    if (!allowed)
    {
        FatalIOErrorInFunction(dict)
            << "U = " << U << " is invalid; allowed: |U| <= " << maximum
            << " m/s" << exit(FatalIOError);
    }
    return U;
}


// ************************************************************************* //
