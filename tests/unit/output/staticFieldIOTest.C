/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    staticFieldIO writes its field at the first write time and links the
    same file into the later ones (one inode, the bytes of a write); when
    the file written last is gone, it writes the field again (the same
    text but for the header's location, the time it is written at).

\*---------------------------------------------------------------------------*/

#include "scratchDir.H"
#include "fileContents.H"
#include "testCase.H"
#include "staticFieldIO.H"
#include "pointFields.H"
#include "OSspecific.H"
#include <gtest/gtest.h>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

} // End anonymous namespace


TEST(staticFieldIO, WrittenOnceThenLinkedIntoLaterTimes)
{
    const fileName dir = testCase::scratchCopy("staticFieldIOCase");
    testCase tc(dir);
    Time& runTime = tc.runTime();
    const pointMesh& pMesh = pointMesh::New(tc.mesh());

    staticFieldIO<pointScalarField> Z
    (
        IOobject("Z", runTime.timeName(), tc.mesh(), IOobject::NO_READ),
        pMesh,
        dimensionedScalar(dimLength, Zero)
    );
    forAll(Z, i)
    {
        Z[i] = 100 + 0.1*i;
    }
    auto writeAt = [&](const scalar t)
    {
        runTime.setTime(t, label(t));
        EXPECT_TRUE
        (
            Z.writeObject
            (
                IOstream::ASCII, IOstream::currentVersion,
                IOstream::UNCOMPRESSED, true
            )
        );
        return runTime.timePath()/"Z";
    };

    const fileName first = writeAt(1);
    const fileName second = writeAt(2);
    const fileName third = writeAt(3);
    ASSERT_TRUE(isFile(first) && isFile(second) && isFile(third));
    EXPECT_NE(inode(first), 0u);
    EXPECT_EQ(inode(second), inode(first)) << "linked, not written again";
    EXPECT_EQ(inode(third), inode(first));
    EXPECT_NE(contents(first).find("nonuniform List<scalar>"), std::string::npos);

    // The file written removed with its time directory (purgeWrite):
    // written again, the same text but for the header's location
    const auto body = [](const std::string& text)
    {
        return text.substr(text.find("dimensions"));
    };
    const std::string text = body(contents(first));
    rmDir(runTime.path()/"1");
    const fileName fourth = writeAt(4);
    ASSERT_TRUE(isFile(fourth));
    EXPECT_NE(inode(fourth), inode(second)) << "written again";
    EXPECT_TRUE(body(contents(fourth)) == text);
    const fileName fifth = writeAt(5);
    EXPECT_EQ(inode(fifth), inode(fourth)) << "linked to the one written last";
}


// ************************************************************************* //
