/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "structureVTKWriter.H"
#include "fastOFstream.H"
#include "exactPrecision.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "symmTensorField.H"
#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Digits of the data (the times have exactPrecision's)
constexpr unsigned dataDigits = 12;

//- Start of the title line of the files written here
const std::string titleStart = "dampm flexibleStructure ";

//- A legacy VTK scalar-data header
void scalarHeader(Foam::Ostream& os, const char* name, const char* type)
{
    os  << "SCALARS " << name << ' ' << type << " 1" << Foam::nl
        << "LOOKUP_TABLE default" << Foam::nl;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::word Foam::structureVTKWriter::vtkName(const label timeIndex) const
{
    return word(name_ + "_" + Foam::name(timeIndex) + ".vtk");
}


Foam::label Foam::structureVTKWriter::indexOf(const word& file) const
{
    const std::string prefix = name_ + "_";
    const std::string suffix = ".vtk";
    if
    (
        file.size() <= prefix.size() + suffix.size()
     || file.compare(0, prefix.size(), prefix) != 0
     || file.compare(file.size() - suffix.size(), suffix.size(), suffix) != 0
    )
    {
        return -1;
    }
    const std::string digits =
        file.substr
        (
            prefix.size(),
            file.size() - prefix.size() - suffix.size()
        );
    label index = -1;
    const bool allDigits =
        std::all_of
        (
            digits.begin(), digits.end(),
            [](const char c) { return std::isdigit(c) != 0; }
        );
    return allDigits && Foam::read(digits, index) ? index : -1;
}


void Foam::structureVTKWriter::collect(const label startTimeIndex)
{
    label removed = 0;
    for (const fileName& file : readDir(dir_, fileName::FILE))
    {
        const label index = indexOf(file);
        scalar time = 0;
        if (index < 0)
        {
            continue;
        }
        if (index > startTimeIndex)
        {
            rm(dir_/file);
            ++removed;
        }
        else if (readTime(dir_/file, time))
        {
            series_[index] = time;
        }
        else
        {
            WarningInFunction
                << dir_/file << " has no time in its title line; left out "
                << "of " << seriesFile_ << endl;
        }
    }
    if (removed)
    {
        Info<< "    removed " << removed << " file(s) of " << name_
            << " after time index " << startTimeIndex << " from " << dir_
            << nl;
    }
}


bool Foam::structureVTKWriter::readTime(const fileName& file, scalar& time)
{
    std::ifstream is(file);
    std::string line;
    std::getline(is, line);
    std::getline(is, line);
    if (!is || line.compare(0, titleStart.size(), titleStart) != 0)
    {
        return false;
    }
    std::istringstream words(line.substr(titleStart.size()));
    std::string name, keyword, value;
    words >> name >> keyword >> value;
    return keyword == "time" && readScalar(value, time);
}


void Foam::structureVTKWriter::writeSeries() const
{
    const fileName tmp(seriesFile_ + ".tmp");
    {
        OFstream os(tmp);
        os.precision(exactPrecision::digits);
        os  << "{" << nl
            << "  \"file-series-version\" : \"1.0\"," << nl
            << "  \"files\" : [";
        label filei = 0;
        for (const auto& indexTime : series_)
        {
            os  << (filei++ ? "," : "") << nl
                << "    { \"name\" : \"" << name_ << '/'
                << vtkName(indexTime.first).c_str() << "\", \"time\" : "
                << indexTime.second << " }";
        }
        os  << nl << "  ]" << nl << "}" << nl;
        if (!os.good())
        {
            FatalErrorInFunction
                << "Cannot write " << tmp << exit(FatalError);
        }
    }
    mv(tmp, seriesFile_);
}


void Foam::structureVTKWriter::writeGeometry
(
    Ostream& os,
    const flexibleStructure& s
)
{
    const structureNodes& n = s.nodes();
    os  << "POINTS " << n.size() << " double" << nl;
    for (label nodei = 0; nodei < n.size(); ++nodei)
    {
        os  << n.x[nodei] << ' ' << n.y[nodei] << ' ' << n.z[nodei] << nl;
    }

    const std::vector<label>& seg = s.ropes().segmentNodes();
    const label nSeg = s.ropes().size();
    if (nSeg)
    {
        os  << "LINES " << nSeg << ' ' << 3*nSeg << nl;
        for (label segi = 0; segi < nSeg; ++segi)
        {
            os  << "2 " << seg[2*segi] << ' ' << seg[2*segi + 1] << nl;
        }
    }

    const std::vector<label>& tri = s.membrane().triangles();
    const label nTri = s.membrane().size();
    if (nTri)
    {
        os  << "POLYGONS " << nTri << ' ' << 4*nTri << nl;
        for (label trii = 0; trii < nTri; ++trii)
        {
            os  << "3 " << tri[3*trii] << ' ' << tri[3*trii + 1] << ' '
                << tri[3*trii + 2] << nl;
        }
    }
}


void Foam::structureVTKWriter::writePointData
(
    Ostream& os,
    const flexibleStructure& s
)
{
    const structureNodes& n = s.nodes();
    os  << "POINT_DATA " << n.size() << nl
        << "VECTORS displacement double" << nl;
    for (label nodei = 0; nodei < n.size(); ++nodei)
    {
        os  << n.x[nodei] - n.x0[nodei] << ' ' << n.y[nodei] - n.y0[nodei]
            << ' ' << n.z[nodei] - n.z0[nodei] << nl;
    }
    os  << "VECTORS velocity double" << nl;
    for (label nodei = 0; nodei < n.size(); ++nodei)
    {
        os  << n.vx[nodei] << ' ' << n.vy[nodei] << ' ' << n.vz[nodei] << nl;
    }
    scalarHeader(os, "fixed", "int");
    for (label nodei = 0; nodei < n.size(); ++nodei)
    {
        os  << label(n.fixed[nodei]) << nl;
    }
}


void Foam::structureVTKWriter::writeCellData
(
    Ostream& os,
    const flexibleStructure& s
)
{
    const label nSeg = s.ropes().size();
    const symmTensorField sigma(s.membrane().cauchyStress(s.nodes()));
    if (nSeg + sigma.size() == 0)
    {
        return;
    }
    os  << "CELL_DATA " << nSeg + sigma.size() << nl
        << "TENSORS stress double" << nl;
    for (label segi = 0; segi < nSeg; ++segi)
    {
        os  << "0 0 0 0 0 0 0 0 0" << nl;
    }
    for (const symmTensor& st : sigma)
    {
        os  << st.xx() << ' ' << st.xy() << ' ' << st.xz() << ' '
            << st.xy() << ' ' << st.yy() << ' ' << st.yz() << ' '
            << st.xz() << ' ' << st.yz() << ' ' << st.zz() << nl;
    }

    scalarHeader(os, "vonMisesStress", "double");
    for (label segi = 0; segi < nSeg; ++segi)
    {
        os  << 0 << nl;
    }
    for (const symmTensor& st : sigma)
    {
        os  << std::sqrt(1.5*magSqr(dev(st))) << nl;
    }

    scalarHeader(os, "tension", "double");
    for (const double T : s.ropes().tension())
    {
        os  << T << nl;
    }
    for (label trii = 0; trii < sigma.size(); ++trii)
    {
        os  << 0 << nl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::structureVTKWriter::structureVTKWriter
(
    const fileName& caseDir,
    const word& name,
    const label startTimeIndex
)
:
    name_(name),
    dir_(caseDir/"VTK"/name),
    seriesFile_(caseDir/"VTK"/(name + ".vtk.series"))
{
    if (isDir(dir_))
    {
        collect(startTimeIndex);
        writeSeries();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fileName Foam::structureVTKWriter::write
(
    const flexibleStructure& s,
    const scalar time,
    const label timeIndex
)
{
    mkDir(dir_);
    const fileName file(dir_/vtkName(timeIndex));
    {
        fastOFstream os(file);
        os.precision(exactPrecision::digits);
        os  << "# vtk DataFile Version 3.0" << nl
            << titleStart.c_str() << name_.c_str() << " time " << time << nl
            << "ASCII" << nl
            << "DATASET POLYDATA" << nl
            << "FIELD FieldData 1" << nl
            << "TIME 1 1 double" << nl
            << time << nl;
        os.precision(dataDigits);
        writeGeometry(os, s);
        writePointData(os, s);
        writeCellData(os, s);
        if (!os.good())
        {
            FatalErrorInFunction
                << "Cannot write " << file << exit(FatalError);
        }
    }
    series_[timeIndex] = time;
    writeSeries();
    return file;
}


// ************************************************************************* //
