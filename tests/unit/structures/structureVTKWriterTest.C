/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    The VTK output of a flexible structure: a loaded barrier written and
    parsed back (counts, displacement, fixed nodes, stress, von Mises,
    tension in VTK's cell order), the series file with its times in order,
    and a restart that drops the later files and keeps the earlier ones,
    with or without the series file. ParaView's reader (pvpython), where
    it is installed, opens the series with its times.

\*---------------------------------------------------------------------------*/

#include "scratchDir.H"
#include "fileContents.H"
#include "structureTestTools.H"
#include "structureVTKWriter.H"
#include "OSspecific.H"
#include <gtest/gtest.h>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

using namespace Foam;
using namespace Foam::structureTest;

namespace
{

//- A legacy VTK polydata file as numbers by section: POINTS, LINES,
//  POLYGONS and each data array by name
struct vtkPolyData
{
    std::string title;
    std::map<std::string, label> count;
    std::map<std::string, std::vector<double>> values;

    explicit vtkPolyData(const fileName& file)
    {
        std::ifstream is(file);
        std::string line;
        std::getline(is, line);
        std::getline(is, title);
        std::string word, name, type;
        label n = 0, size = 0, nData = 0;
        while (is >> word)
        {
            if (word == "POINTS")
            {
                is >> n >> type;
                count[word] = n;
                read(is, word, 3*n);
            }
            else if (word == "LINES" || word == "POLYGONS")
            {
                is >> n >> size;
                count[word] = n;
                read(is, word, size);
            }
            else if (word == "POINT_DATA" || word == "CELL_DATA")
            {
                is >> nData;
                count[word] = nData;
            }
            else if (word == "VECTORS" || word == "TENSORS")
            {
                is >> name >> type;
                read(is, name, (word == "VECTORS" ? 3 : 9)*nData);
            }
            else if (word == "SCALARS")
            {
                is >> name >> type >> n >> word >> type;  // LOOKUP_TABLE
                read(is, name, nData);
            }
            else if (word == "TIME")
            {
                is >> n >> size >> type;
                read(is, word, 1);
            }
        }
    }

    void read(std::istream& is, const std::string& key, const label n)
    {
        std::vector<double>& v = values[key];
        v.resize(n);
        for (double& x : v)
        {
            is >> x;
        }
    }
};


//- The (name, time) entries of a .vtk.series file
std::vector<std::pair<std::string, double>> seriesOf(const fileName& file)
{
    const std::string s = contents(file);
    const std::regex entry
    (
        "\\{ \"name\" : \"([^\"]+)\", \"time\" : ([-+.eE0-9]+) \\}"
    );
    std::vector<std::pair<std::string, double>> files;
    for
    (
        std::sregex_iterator it(s.begin(), s.end(), entry), end;
        it != end;
        ++it
    )
    {
        files.emplace_back((*it)[1], std::stod((*it)[2]));
    }
    return files;
}


//- A fresh case folder for the writer
fileName caseDir(const word& name)
{
    const fileName dir(scratchDir(name));
    if (isDir(dir))
    {
        rmDir(dir);
    }
    mkDir(dir);
    return dir;
}


//- The barrier, loaded, after 20 flow steps of 1 ms: the ropes pulled
//  beyond their pretension
flexibleStructure loaded()
{
    flexibleStructure s(dictionaryOf(barrier + ropes), ".");
    loadBarrier(s);
    for (label stepi = 0; stepi < 20; ++stepi)
    {
        s.subCycle(1e-3);
    }
    return s;
}

} // End anonymous namespace


TEST(structureVTKWriter, FileHoldsTheDeformedStructure)
{
    const flexibleStructure s = loaded();
    const fileName dir = caseDir("structureVTKWriterFile");
    structureVTKWriter writer(dir, "net", 0);
    const fileName file = writer.write(s, 0.02, 20);
    EXPECT_EQ(file, dir/"VTK/net/net_20.vtk");

    const vtkPolyData vtk(file);
    const structureNodes& n = s.nodes();
    const label nSeg = s.ropes().size();
    const label nTri = s.membrane().size();
    ASSERT_EQ(vtk.count.at("POINTS"), n.size());
    ASSERT_EQ(vtk.count.at("LINES"), nSeg);
    ASSERT_EQ(vtk.count.at("POLYGONS"), nTri);
    ASSERT_EQ(vtk.count.at("POINT_DATA"), n.size());
    ASSERT_EQ(vtk.count.at("CELL_DATA"), nSeg + nTri);
    // The time reads back exactly
    EXPECT_EQ(vtk.values.at("TIME")[0], 0.02);
    EXPECT_EQ(vtk.title.substr(0, 33), "dampm flexibleStructure net time ");
    EXPECT_EQ(std::stod(vtk.title.substr(33)), 0.02);

    // The node that moved most, at 12 digits
    label far = 0;
    for (label nodei = 0; nodei < n.size(); ++nodei)
    {
        if (mag(n.position(nodei) - n.referencePosition(nodei))
          > mag(n.position(far) - n.referencePosition(far)))
        {
            far = nodei;
        }
    }
    const std::vector<double>& d = vtk.values.at("displacement");
    EXPECT_NEAR(d[3*far + 1], n.y[far] - n.y0[far], 1e-12);
    EXPECT_GT(d[3*far + 1], 1e-3);
    const std::vector<double>& fixed = vtk.values.at("fixed");
    const label anchored = s.anchors().nodes(0)[0];
    EXPECT_EQ(fixed[anchored], 1);
    EXPECT_EQ(fixed[far], 0);

    // Cells: the rope segments, then the triangles
    const symmTensorField sigma(s.membrane().cauchyStress(n));
    const std::vector<double>& stress = vtk.values.at("stress");
    const std::vector<double>& vonMises = vtk.values.at("vonMisesStress");
    const std::vector<double>& tension = vtk.values.at("tension");
    EXPECT_NEAR(tension[0], s.ropes().tension()[0], 1e-11*tension[0]);
    EXPECT_GT(tension[0], 200);
    EXPECT_EQ(stress[0], 0);
    EXPECT_EQ(vonMises[nSeg - 1], 0);
    const label trii = nTri/2;
    const double* st = &stress[9*(nSeg + trii)];
    EXPECT_NEAR(st[0], sigma[trii].xx(), 1e-11*mag(sigma[trii]));
    EXPECT_NEAR(st[5], sigma[trii].yz(), 1e-11*mag(sigma[trii]));
    EXPECT_EQ(st[5], st[7]);
    EXPECT_EQ(tension[nSeg + trii], 0);
    const double vm = std::sqrt
    (
        0.5*(sqr(st[0] - st[4]) + sqr(st[4] - st[8]) + sqr(st[8] - st[0]))
      + 3*(sqr(st[1]) + sqr(st[2]) + sqr(st[5]))
    );
    EXPECT_NEAR(vonMises[nSeg + trii], vm, 1e-10*vm);
    EXPECT_GT(vm, 1e5);
}


TEST(structureVTKWriter, RestartDropsTheLaterFilesOfTheSeries)
{
    const flexibleStructure s = loaded();
    const fileName dir = caseDir("structureVTKWriterSeries");
    {
        structureVTKWriter writer(dir, "net", 0);
        for (const label index : {0, 10, 20, 30})
        {
            writer.write(s, 0.01*index, index);
        }
    }
    const fileName series = dir/"VTK/net.vtk.series";
    std::vector<std::pair<std::string, double>> files = seriesOf(series);
    ASSERT_EQ(files.size(), 4u);
    EXPECT_EQ(files[1].first, "net/net_10.vtk");
    EXPECT_EQ(files[3].first, "net/net_30.vtk");
    EXPECT_EQ(files[1].second, 0.1);
    EXPECT_EQ(files[3].second, 0.3);

    // Restart at index 20: 30 goes, 0 to 20 stay, another file is ignored
    std::ofstream(dir/"VTK/net/net_notes.vtk") << "not of the series\n";
    structureVTKWriter restarted(dir, "net", 20);
    files = seriesOf(series);
    ASSERT_EQ(files.size(), 3u);
    EXPECT_EQ(files[2].first, "net/net_20.vtk");
    EXPECT_EQ(files[2].second, 0.2);
    EXPECT_FALSE(isFile(dir/"VTK/net/net_30.vtk"));
    EXPECT_TRUE(isFile(dir/"VTK/net/net_notes.vtk"));

    restarted.write(s, 0.25, 25);
    files = seriesOf(series);
    ASSERT_EQ(files.size(), 4u);
    EXPECT_EQ(files[3].first, "net/net_25.vtk");
    EXPECT_EQ(files[3].second, 0.25);

    // Without the series file (lost, or never written), from the files
    rm(series);
    const structureVTKWriter rebuilt(dir, "net", 10);
    files = seriesOf(series);
    ASSERT_EQ(files.size(), 2u);
    EXPECT_EQ(files[0].second, 0);
    EXPECT_EQ(files[1].first, "net/net_10.vtk");
    EXPECT_EQ(files[1].second, 0.1);
    EXPECT_FALSE(isFile(dir/"VTK/net/net_20.vtk"));
}


TEST(structureVTKWriterCase, ParaViewOpensTheSeries)
{
    if (std::system("command -v pvpython > /dev/null") != 0)
    {
        GTEST_SKIP() << "no pvpython (etc/prerequisites -paraview)";
    }
    const flexibleStructure s = loaded();
    const fileName dir = caseDir("structureVTKWriterParaView");
    structureVTKWriter writer(dir, "net", 0);
    writer.write(s, 0.01, 1);
    writer.write(s, 0.02, 2);

    // Points, cells and the tension's range at the second time
    std::ofstream(dir/"read.py")
        << "from paraview.simple import *\n"
        << "r = OpenDataFile('" << writer.seriesFile().c_str() << "')\n"
        << "times = list(r.TimestepValues)\n"
        << "r.UpdatePipeline(times[-1])\n"
        << "d = servermanager.Fetch(r)\n"
        << "t = d.GetCellData().GetArray('tension').GetRange()\n"
        << "print('READ', len(times), times[-1], d.GetNumberOfPoints(),"
        << " d.GetNumberOfCells(), t[1])\n";
    const fileName out(dir/"read.log");
    const std::string command =
        "pvpython --no-mpi " + dir/"read.py" + " > " + out + " 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;

    std::ifstream is(out);
    std::string line, word;
    while (std::getline(is, line) && line.compare(0, 5, "READ ") != 0)
    {}
    std::istringstream read(line);
    label nTimes = 0, nPoints = 0, nCells = 0;
    double last = 0, maxTension = 0;
    read >> word >> nTimes >> last >> nPoints >> nCells >> maxTension;
    EXPECT_EQ(nTimes, 2) << line;
    EXPECT_DOUBLE_EQ(last, 0.02);
    EXPECT_EQ(nPoints, s.nodes().size());
    EXPECT_EQ(nCells, s.ropes().size() + s.membrane().size());
    double maxT = 0;
    for (const double T : s.ropes().tension())
    {
        maxT = max(maxT, T);
    }
    EXPECT_NEAR(maxTension, maxT, 1e-9*maxT);
}


// ************************************************************************* //
