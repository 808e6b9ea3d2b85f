/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "fastOFstream.H"
#include "ListPolicy.H"
#include "token.H"
#include <type_traits>

// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

template<class T>
void Foam::fastOFstream::writeList(Ostream& os, const UList<T>& list)
{
    // UList::writeList writes a contiguous list of more than short_length
    // elements a line each
    fastOFstream* fast = dynamic_cast<fastOFstream*>(&os);
    const label len = list.size();
    if
    (
        fast
     && os.format() == IOstream::ASCII
     && is_contiguous<T>::value
     && std::is_same<typename pTraits<T>::cmptType, double>::value
     && len > Detail::ListPolicy::short_length<T>::value
     && !list.uniform()
    )
    {
        os  << nl << len << nl << token::BEGIN_LIST << nl;
        fast->writeLines
        (
            reinterpret_cast<const double*>(list.cdata()), len,
            pTraits<T>::nComponents
        );
        os  << token::END_LIST << nl;
    }
    else
    {
        os  << list;
    }
}


template<class Type, template<class> class PatchField, class GeoMesh>
bool Foam::fastFieldData<Foam::GeometricField<Type, PatchField, GeoMesh>>::
write
(
    const GeometricField<Type, PatchField, GeoMesh>& field,
    Ostream& os
)
{
    // DimensionedField::writeData
    os.writeEntry("dimensions", field.dimensions());
    field.oriented().writeEntry(os);
    os  << nl << nl;

    // Field::writeEntry("internalField"), its list as UList::writeEntry
    const auto& values = field.primitiveField();
    os.writeKeyword("internalField");
    if (is_contiguous<Type>::value && values.uniform())
    {
        os  << word("uniform") << token::SPACE << values.first();
    }
    else
    {
        os  << word("nonuniform") << token::SPACE;
        if (values.size())
        {
            const word tag = "List<" + word(pTraits<Type>::typeName) + '>';
            if (token::compound::isCompound(tag))
            {
                os  << tag << token::SPACE;
            }
            fastOFstream::writeList(os, values);
        }
        else if (os.format() == IOstream::ASCII)
        {
            os  << label(0) << token::BEGIN_LIST << token::END_LIST;
        }
        else
        {
            os  << label(0);
        }
    }
    os  << token::END_STATEMENT << nl;

    // GeometricField's operator<<
    os  << nl;
    field.boundaryField().writeEntry("boundaryField", os);
    os.check(FUNCTION_NAME);
    return os.good();
}


// ************************************************************************* //
