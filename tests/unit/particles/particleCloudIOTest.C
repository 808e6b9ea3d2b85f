/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    The lagrangian cloud written by particleCloudIO: OpenFOAM's foamToVTK
    (what paraFoam users rely on) finds every particle with its field values
    (v1912 silently shows none when the format is wrong), and the cloud
    reads back into particleArrays unchanged.

\*---------------------------------------------------------------------------*/

#include "scratchDir.H"
#include "particleCloudIO.H"
#include "testCase.H"
#include "OSspecific.H"
#include <gtest/gtest.h>
#include <fstream>
#include <random>
#include <sstream>

using namespace Foam;

namespace
{

// foamToVTK's ASCII output: 6 significant digits (relative)
constexpr double vtkTol = 1e-5;

// A copy of the box2D test mesh in a fresh case folder
fileName freshCase(const word& name)
{
    return testCase::scratchCopy(name);
}

particleArrays makeCloud(const label n)
{
    particleArrays p;
    const label h = p.addField("h", particleArrays::fieldKind::scalar);
    p.addField("scratch", particleArrays::fieldKind::internal, 0, 4);
    p.append(n);
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> u(0.01, 0.99);
    for (label i = 0; i < n; ++i)
    {
        p.component(particleArrays::X)[i] = 10*u(gen);
        p.component(particleArrays::Y)[i] = 5*u(gen);
        p.component(particleArrays::Z)[i] = u(gen);
        p.component(particleArrays::UX)[i] = u(gen) - 0.5;
        p.component(particleArrays::UY)[i] = 2*u(gen);
        p.component(particleArrays::M)[i] = 1000*u(gen);
        p.component(particleArrays::VOL)[i] = u(gen);
        p.component(h)[i] = 1.0/3.0 + i;
    }
    return p;
}

// Values of a named DataArray in an ASCII VTK XML file (.vtp)
std::vector<double> vtpArray(const std::string& file, const std::string& name)
{
    std::ifstream is(file);
    std::string line;
    const std::string tag = "Name='" + name + "'";
    std::vector<double> v;
    while (std::getline(is, line))
    {
        if (line.find("<DataArray") != std::string::npos
         && line.find(tag) != std::string::npos)
        {
            while (std::getline(is, line)
                && line.find("</DataArray>") == std::string::npos)
            {
                std::istringstream ls(line);
                double x;
                while (ls >> x)
                {
                    v.push_back(x);
                }
            }
            break;
        }
    }
    return v;
}

} // End anonymous namespace


TEST(particleCloudIOCase, FoamToVTKShowsEveryParticleWithItsFields)
{
    const fileName dir = freshCase("cloudIOCase");
    testCase tc(dir);
    tc.runTime().setTime(0.5, 1);
    const mpmGrid grid(tc.mesh());
    const particleArrays p = makeCloud(37);
    particleCloudIO cloudIO("mpmCloud", p, grid);
    ASSERT_TRUE(cloudIO.write());

    const std::string cmd =
        "foamToVTK -ascii -time 0.5 -case " + dir + " > " + dir
      + "/log.foamToVTK 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << "see " << dir/"log.foamToVTK";

    // The lagrangian file of the cloud
    const std::string find =
        "find " + dir + "/VTK -path '*lagrangian*mpmCloud*' -name '*.vtp'"
        " > " + dir + "/vtkFiles";
    ASSERT_EQ(std::system(find.c_str()), 0);
    std::ifstream files(dir/"vtkFiles");
    std::string vtk;
    ASSERT_TRUE(bool(std::getline(files, vtk))) << "no lagrangian VTK file";

    const std::vector<double> pts = vtpArray(vtk, "Points");
    ASSERT_EQ(label(pts.size()), 3*p.size());
    const std::vector<double> h = vtpArray(vtk, "h");
    ASSERT_EQ(label(h.size()), p.size());
    const std::vector<double> U = vtpArray(vtk, "U");
    ASSERT_EQ(label(U.size()), 3*p.size());
    const label hc = p.field("h").first;
    for (label i = 0; i < p.size(); ++i)
    {
        // foamToVTK writes floats with 6 significant digits
        EXPECT_NEAR(pts[3*i], p.component(particleArrays::X)[i], vtkTol*10);
        EXPECT_NEAR(pts[3*i + 1], p.component(particleArrays::Y)[i], vtkTol*5);
        EXPECT_NEAR(h[i], p.component(hc)[i], vtkTol*p.component(hc)[i]);
        EXPECT_NEAR(U[3*i + 1], p.component(particleArrays::UY)[i], vtkTol*2);
    }
    EXPECT_TRUE(vtpArray(vtk, "scratch").empty());
}


// A cloud written at a time of a case, in a format
particleArrays writeCloud
(
    testCase& tc,
    const scalar t,
    const particleArrays& p,
    const IOstream::streamFormat fmt
)
{
    tc.runTime().setTime(t, 1);
    const mpmGrid grid(tc.mesh());
    particleCloudIO cloudIO("mpmCloud", p, grid);
    EXPECT_TRUE
    (
        cloudIO.writeObject
        (
            fmt, IOstream::currentVersion, IOstream::UNCOMPRESSED, true
        )
    );
    particleArrays q;
    q.addField("h", particleArrays::fieldKind::scalar);
    particleCloudIO::read(q, tc.mesh(), "mpmCloud", tc.runTime().timeName());
    return q;
}


TEST(particleCloudIOCase, CloudReadsBackBitForBitInAsciiAndBinary)
{
    const fileName dir = freshCase("cloudReadCase");
    testCase tc(dir);
    // ASCII at writePrecision 6: the cloud is still written exactly
    IOstream::defaultPrecision(6);
    const particleArrays p = makeCloud(50);
    for (const IOstream::streamFormat fmt : {IOstream::ASCII, IOstream::BINARY})
    {
        const particleArrays q =
            writeCloud(tc, fmt == IOstream::ASCII ? 1.25 : 1.5, p, fmt);
        ASSERT_EQ(q.size(), p.size());
        for (label c = 0; c <= particleArrays::VOL; ++c)
        {
            for (label i = 0; i < p.size(); ++i)
            {
                EXPECT_EQ(q.component(c)[i], p.component(c)[i])
                    << "column " << c << ", particle " << i;
            }
        }
        for (label i = 0; i < p.size(); ++i)
        {
            EXPECT_EQ(q.component(q.field("h").first)[i],
                p.component(p.field("h").first)[i]);
        }
    }
    // The binary file is binary (OpenFOAM's header says so)
    std::ifstream is(dir/"1.5"/"lagrangian"/"mpmCloud"/"positions");
    const std::string text
    (
        (std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>()
    );
    EXPECT_NE(text.find("format      binary"), std::string::npos);
}


TEST(particleCloudIOCase, MissingFieldShortListAndBadValuesAreRefused)
{
    const fileName dir = freshCase("cloudBadCase");
    testCase tc(dir);
    const particleArrays p = makeCloud(20);
    writeCloud(tc, 2, p, IOstream::ASCII);
    const fileName cloud = dir/"2"/"lagrangian"/"mpmCloud";

    // A field the particles have but the cloud lacks
    particleArrays q;
    q.addField("h", particleArrays::fieldKind::scalar);
    q.addField("notWritten", particleArrays::fieldKind::scalar);
    try
    {
        particleCloudIO::read(q, tc.mesh(), "mpmCloud", "2");
        ADD_FAILURE() << "a missing field was accepted";
    }
    catch (const Foam::error& e)
    {
        EXPECT_NE(e.message().find("notWritten"), std::string::npos)
            << e.message();
    }

    // A field one value short
    {
        std::ifstream is(cloud/"h");
        std::string text
        (
            (std::istreambuf_iterator<char>(is)),
            std::istreambuf_iterator<char>()
        );
        const std::size_t last = text.rfind(')');
        const std::size_t cut = text.rfind('\n', text.rfind('\n', last) - 1);
        text.erase(cut, text.rfind('\n', last) - cut);
        std::ofstream(cloud/"h") << text;
    }
    particleArrays r;
    r.addField("h", particleArrays::fieldKind::scalar);
    EXPECT_THROW
    (
        particleCloudIO::read(r, tc.mesh(), "mpmCloud", "2"),
        Foam::error
    );

    // Negative mass, a speed above maxSpeed, a particle outside the mesh
    const mpmGrid grid(tc.mesh());
    for (const label c : {particleArrays::M, particleArrays::UX,
        particleArrays::X})
    {
        particleArrays bad(p);
        bad.component(c)[7] = c == particleArrays::M ? -1 : 1e200;
        try
        {
            particleCloudIO::checkCloud(bad, grid, cloud);
            ADD_FAILURE() << "column " << c << " was accepted";
        }
        catch (const Foam::error& e)
        {
            EXPECT_NE(e.message().find("particle 7"), std::string::npos)
                << e.message();
        }
    }
}


// ************************************************************************* //
