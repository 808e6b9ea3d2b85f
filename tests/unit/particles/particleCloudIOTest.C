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

// Values are written with at least 12 significant digits
constexpr double ioTol = 1e-10;

// foamToVTK's ASCII output: 6 significant digits (relative)
constexpr double vtkTol = 1e-5;

// A copy of the box2D test mesh in a fresh case folder
fileName freshCase(const word& name)
{
    const fileName dir = fileName(DAMPM_TEST_MESHES).path()/name;
    rmDir(dir);
    mkDir(dir);
    cp(testCase::meshDir("box2D")/"system", dir);
    cp(testCase::meshDir("box2D")/"constant", dir);
    return dir;
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
        p.column(particleArrays::X)[i] = 10*u(gen);
        p.column(particleArrays::Y)[i] = 5*u(gen);
        p.column(particleArrays::Z)[i] = u(gen);
        p.column(particleArrays::UX)[i] = u(gen) - 0.5;
        p.column(particleArrays::UY)[i] = 2*u(gen);
        p.column(particleArrays::M)[i] = 1000*u(gen);
        p.column(h)[i] = 1.0/3.0 + i;
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
        EXPECT_NEAR(pts[3*i], p.column(particleArrays::X)[i], vtkTol*10);
        EXPECT_NEAR(pts[3*i + 1], p.column(particleArrays::Y)[i], vtkTol*5);
        EXPECT_NEAR(h[i], p.column(hc)[i], vtkTol*p.column(hc)[i]);
        EXPECT_NEAR(U[3*i + 1], p.column(particleArrays::UY)[i], vtkTol*2);
    }
    EXPECT_TRUE(vtpArray(vtk, "scratch").empty());
}


TEST(particleCloudIOCase, CloudReadsBackUnchanged)
{
    const fileName dir = freshCase("cloudReadCase");
    testCase tc(dir);
    tc.runTime().setTime(1.25, 1);
    const mpmGrid grid(tc.mesh());
    const particleArrays p = makeCloud(50);
    particleCloudIO cloudIO("mpmCloud", p, grid);
    ASSERT_TRUE(cloudIO.write());
    ASSERT_TRUE(particleCloudIO::found(tc.mesh(), "mpmCloud", "1.25"));

    particleArrays q;
    q.addField("h", particleArrays::fieldKind::scalar);
    q.addField("notWritten", particleArrays::fieldKind::scalar, -1);
    const wordList missing =
        particleCloudIO::read(q, tc.mesh(), "mpmCloud", "1.25");
    ASSERT_EQ(q.size(), p.size());
    ASSERT_EQ(missing.size(), 1);
    EXPECT_EQ(missing[0], "notWritten");
    for (label c = 0; c <= particleArrays::VOL; ++c)
    {
        for (label i = 0; i < p.size(); ++i)
        {
            EXPECT_NEAR(q.column(c)[i], p.column(c)[i],
                ioTol*(1 + std::abs(p.column(c)[i])));
        }
    }
    for (label i = 0; i < p.size(); ++i)
    {
        EXPECT_NEAR(q.column(q.field("h").first)[i],
            p.column(p.field("h").first)[i], ioTol*(1 + i));
        EXPECT_EQ(q.column(q.field("notWritten").first)[i], -1);
    }
}


// ************************************************************************* //
