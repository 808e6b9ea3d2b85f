/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    noBedFriction: selected by 'none' and when bedFriction is not given,
    inactive (the solver skips it), and adds nothing to the columns'
    resistance coefficients.

\*---------------------------------------------------------------------------*/

#include "bedFrictionModel.H"
#include "columnArrays.H"
#include <gtest/gtest.h>

using namespace Foam;

TEST(noBedFriction, SelectedByDefaultInactiveAndAddsNothing)
{
    columnArrays cols({0.5, 2}, {1, 0.25}, {1, 0.8});
    cols.s = {3, 4};
    cols.k1 = {5, 6};
    cols.k2 = {7, 8};

    IStringStream empty("rho 1000;");
    for (const dictionary& dict : {modelDict("bedFriction", "none", ""),
         dictionary(empty)})
    {
        const autoPtr<bedFrictionModel> friction(bedFrictionModel::New(dict));
        EXPECT_EQ(word(friction->type()), "none");
        EXPECT_FALSE(friction->active());
        friction->addResistance(cols.view());
    }
    EXPECT_EQ(cols.s, std::vector<double>({3, 4}));
    EXPECT_EQ(cols.k1, std::vector<double>({5, 6}));
    EXPECT_EQ(cols.k2, std::vector<double>({7, 8}));
}


// ************************************************************************* //
