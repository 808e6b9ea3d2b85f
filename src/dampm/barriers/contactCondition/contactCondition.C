/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "contactCondition.H"
#include "knownKeywords.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::contactCondition::contactType>
Foam::contactCondition::contactTypeNames
({
    { contactType::slip, "slip" },
    { contactType::noSlip, "noSlip" },
    { contactType::Coulomb, "Coulomb" },
});


const Foam::wordList Foam::contactCondition::keywords
({
    "contact", "frictionCoefficient"
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactCondition::contactCondition(const dictionary& dict)
:
    type_(contactTypeNames.get("contact", dict)),
    friction_(0)
{
    knownKeywords::add(dict, keywords);

    if (type_ == contactType::Coulomb)
    {
        friction_ = dict.get<scalar>("frictionCoefficient");
        if (!(friction_ >= 0))
        {
            FatalIOErrorInFunction(dict)
                << "frictionCoefficient = " << friction_ << " is invalid;"
                << " allowed: >= 0" << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::contactCondition::describe(Ostream& os) const
{
    os  << contactTypeNames[type_];
    if (type_ == contactType::Coulomb)
    {
        os  << " (friction coefficient " << friction_ << ")";
    }
}


// ************************************************************************* //
