/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "terrainRaster.H"
#include "fpTrapsHeld.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "exactPrecision.H"
#include "geoTiffCodec.H"
#include "DynamicList.H"
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <type_traits>
#include <string>
#include <utility>
#include <vector>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::terrainRaster::noDataPolicy>
Foam::terrainRaster::noDataPolicyNames
({
    { noDataPolicy::fail, "fail" },
    { noDataPolicy::fill, "fill" },
});


const Foam::scalar Foam::terrainRaster::noBound =
    std::numeric_limits<scalar>::max();


namespace
{

//- The break points of [a, b] in sample units: a, the whole sample lines
//  strictly between a and b within the hull [0, n - 1], and b
void sampleBreaks
(
    const Foam::scalar a,
    const Foam::scalar b,
    const Foam::label n,
    Foam::DynamicList<Foam::scalar>& at
)
{
    at.clear();
    at.append(a);
    const Foam::scalar first = std::max(std::floor(a) + 1, Foam::scalar(0));
    const Foam::scalar last = std::min(std::ceil(b) - 1, Foam::scalar(n - 1));
    for (Foam::label k = Foam::label(first); k <= Foam::label(last); ++k)
    {
        at.append(k);
    }
    at.append(b);
}


static_assert
(
    std::is_same<Foam::scalar, double>::value,
    "terrainRaster reads GDAL bands as double into scalar samples"
);

//- NODATA_value of written rasters
constexpr double writtenNoData = -9999;

//- Header keys of an ESRI ASCII grid (lower case) and their indices
enum ascKey
{
    NCOLS, NROWS, XLLCORNER, XLLCENTER, YLLCORNER, YLLCENTER,
    CELLSIZE, DX, DY, NODATA, nAscKeys
};

const char* const ascKeyNames[nAscKeys] =
{
    "ncols", "nrows", "xllcorner", "xllcenter", "yllcorner", "yllcenter",
    "cellsize", "dx", "dy", "NODATA_value"
};

const char* const ascHeader =
    "an ESRI ASCII grid header has the keys ncols, nrows, xllcorner or"
    " xllcenter, yllcorner or yllcenter, cellsize (or dx and dy) and"
    " optionally NODATA_value (any case), each followed by one number";


//- Find the next blank-separated word of line from pos: [b, e)
bool nextWord
(
    const std::string& line,
    std::string::size_type& pos,
    std::string::size_type& b,
    std::string::size_type& e
)
{
    static const char* const blanks = " \t\r\f\v";
    b = line.find_first_not_of(blanks, pos);
    if (b == std::string::npos)
    {
        pos = line.size();
        return false;
    }
    e = std::min(line.find_first_of(blanks, b), line.size());
    pos = e;
    return true;
}


//- What parseNumber found
enum class parsed
{
    number,             // a decimal number (nan and inf included)
    notANumber,         // hex, trailing characters, a word
    outOfRange          // beyond a double (1e400, 1e-400)
};


//- Parse line[b, e) as a whole decimal number, as std::from_chars reads
//  it (no hex, unlike strtod) with an optional leading '+'
parsed parseNumber
(
    const std::string& line,
    const std::string::size_type b,
    const std::string::size_type e,
    double& v
)
{
    const char* first = line.c_str() + b;
    const char* const last = line.c_str() + e;
    if (last - first > 1 && *first == '+' && first[1] != '-')
    {
        ++first;
    }
    const auto r = std::from_chars(first, last, v);
    if (r.ptr != last)
    {
        return parsed::notANumber;
    }
    return
        r.ec == std::errc() ? parsed::number
      : r.ec == std::errc::result_out_of_range ? parsed::outOfRange
      : parsed::notANumber;
}


//- Does the word start like a number (digit, sign or point)?
bool numberLike(const std::string& line, const std::string::size_type b)
{
    const char c = line[b];
    return std::isdigit(uint8_t(c)) || c == '+' || c == '-' || c == '.';
}


//- Are a and b the same but for case?
bool sameKey(const std::string& a, const char* b)
{
    std::string::size_type i = 0;
    for (; i < a.size() && b[i]; ++i)
    {
        if (std::tolower(uint8_t(a[i])) != std::tolower(uint8_t(b[i])))
        {
            return false;
        }
    }
    return i == a.size() && !b[i];
}


//- Is v a positive integer that fits a label?
bool isCount(const double v)
{
    return v >= 1 && v < 1e9 && v == std::floor(v);
}


} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::terrainRaster::readAsc()
{
    // Not through GDAL's AAIGrid driver: it reads 'abc' as 0, a missing
    // value as 0 and opens a negative cell size, and gives no line; a check
    // of its result would parse every value again (doc/inputReaders.md)
    IFstream is(file_);
    if (!is.good())
    {
        FatalIOErrorInFunction(is)
            << "cannot open the ESRI ASCII grid " << file_
            << exit(FatalIOError);
    }
    std::istream& in = is.stdStream();

    // Header: key-value lines up to the first line that starts with a value
    // (a word like a number, or nan or inf)
    double header[nAscKeys] = {};
    label keyLine[nAscKeys] = {};
    std::string line;
    std::string::size_type pos, b, e;
    label lineNo = 0;
    bool pending = false;

    while (std::getline(in, line))
    {
        is.lineNumber(++lineNo);
        if (lineNo == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0)
        {
            line.erase(0, 3);
        }
        pos = 0;
        double v;
        if (!nextWord(line, pos, b, e))
        {
            continue;
        }
        const std::string key(line, b, e - b);
        int k = 0;
        while (k < nAscKeys && !sameKey(key, ascKeyNames[k]))
        {
            ++k;
        }
        if
        (
            k == nAscKeys
         && (
                numberLike(line, b)
             || parseNumber(line, b, e, v) == parsed::number
            )
        )
        {
            pending = true;
            break;
        }
        if (k == nAscKeys)
        {
            FatalIOErrorInFunction(is)
                << "unknown header key '" << line.substr(b, e - b).c_str()
                << "' in the ESRI ASCII grid " << file_ << "; " << ascHeader
                << exit(FatalIOError);
        }

        // Keys that give the same thing twice
        int other = -1;
        switch (k)
        {
            case XLLCORNER: other = XLLCENTER; break;
            case XLLCENTER: other = XLLCORNER; break;
            case YLLCORNER: other = YLLCENTER; break;
            case YLLCENTER: other = YLLCORNER; break;
            case CELLSIZE: other = keyLine[DX] ? DX : DY; break;
            case DX: case DY: other = CELLSIZE; break;
            default: break;
        }
        if (keyLine[k] || (other >= 0 && keyLine[other]))
        {
            const int first = keyLine[k] ? k : other;
            FatalIOErrorInFunction(is)
                << "duplicate header key '" << ascKeyNames[k]
                << "': '" << ascKeyNames[first] << "' was given at line "
                << keyLine[first] << "; " << ascHeader
                << exit(FatalIOError);
        }

        if
        (
            !nextWord(line, pos, b, e)
         || parseNumber(line, b, e, v) != parsed::number
         || nextWord(line, pos, b, e)
        )
        {
            FatalIOErrorInFunction(is)
                << "header key '" << ascKeyNames[k] << "' needs one number: '"
                << line.c_str() << "' (decimal, no hexadecimal, within the"
                << " range of a double); " << ascHeader
                << exit(FatalIOError);
        }
        header[k] = v;
        keyLine[k] = lineNo;
    }

    // Check the header
    const bool xCorner = keyLine[XLLCORNER];
    const bool yCorner = keyLine[YLLCORNER];
    const int required[] =
    {
        NCOLS, NROWS, xCorner ? XLLCORNER : XLLCENTER,
        yCorner ? YLLCORNER : YLLCENTER,
        keyLine[CELLSIZE] || (!keyLine[DX] && !keyLine[DY])
      ? CELLSIZE : (keyLine[DX] ? DY : DX)
    };
    for (const int k : required)
    {
        if (!keyLine[k])
        {
            FatalIOErrorInFunction(is)
                << "missing header key '" << ascKeyNames[k]
                << "' in the ESRI ASCII grid " << file_ << "; " << ascHeader
                << exit(FatalIOError);
        }
    }
    if (xCorner != yCorner)
    {
        FatalIOErrorInFunction(is)
            << "header keys '" << ascKeyNames[required[2]] << "' and '"
            << ascKeyNames[required[3]] << "' mix the corner and centre"
            << " forms; allowed: xllcorner with yllcorner, or xllcenter with"
            << " yllcenter"
            << exit(FatalIOError);
    }
    for (const int k : {NCOLS, NROWS})
    {
        if (!isCount(header[k]))
        {
            is.lineNumber(keyLine[k]);
            FatalIOErrorInFunction(is)
                << "header key '" << ascKeyNames[k] << "' = " << header[k]
                << " is invalid; allowed: a positive integer"
                << exit(FatalIOError);
        }
    }
    for (const int k : {CELLSIZE, DX, DY})
    {
        if (keyLine[k] && !(header[k] > 0 && std::isfinite(header[k])))
        {
            is.lineNumber(keyLine[k]);
            FatalIOErrorInFunction(is)
                << "header key '" << ascKeyNames[k] << "' = " << header[k]
                << " is invalid; allowed: a finite number > 0 [m]"
                << exit(FatalIOError);
        }
    }
    for (const int k : required)
    {
        if (!std::isfinite(header[k]))
        {
            is.lineNumber(keyLine[k]);
            FatalIOErrorInFunction(is)
                << "header key '" << ascKeyNames[k] << "' = " << header[k]
                << " is invalid; allowed: a finite number"
                << exit(FatalIOError);
        }
    }
    if (header[NCOLS]*header[NROWS] > labelMax)
    {
        FatalIOErrorInFunction(is)
            << "ncols x nrows = " << header[NCOLS] << " x " << header[NROWS]
            << " is too large; allowed: at most " << labelMax << " values"
            << exit(FatalIOError);
    }

    nx_ = label(header[NCOLS]);
    ny_ = label(header[NROWS]);
    dx_ = keyLine[CELLSIZE] ? header[CELLSIZE] : header[DX];
    dy_ = keyLine[CELLSIZE] ? header[CELLSIZE] : header[DY];
    mapOrigin_.x() = header[required[2]] + (xCorner ? dx_/2 : 0);
    mapOrigin_.y() = header[required[3]] + (yCorner ? dy_/2 : 0);
    const bool hasNoData = keyLine[NODATA];
    const double noData = header[NODATA];

    // Samples: rows north to south, any line breaks
    const label n = nx_*ny_;
    values_.setSize(n);
    label count = 0;
    while (pending || std::getline(in, line))
    {
        if (!pending)
        {
            is.lineNumber(++lineNo);
        }
        pending = false;
        pos = 0;
        while (nextWord(line, pos, b, e))
        {
            double v = 0;
            const parsed kind = parseNumber(line, b, e, v);
            if (kind == parsed::notANumber)
            {
                FatalIOErrorInFunction(is)
                    << "value '" << line.substr(b, e - b).c_str() << "' (row "
                    << count/nx_ + 1 << ", column " << count % nx_ + 1
                    << ") is not a number; expected ncols x nrows = "
                    << nx_ << " x " << ny_ << " decimal numbers after the"
                    << " header (no hexadecimal, nothing appended)"
                    << exit(FatalIOError);
            }
            if (count == n)
            {
                FatalIOErrorInFunction(is)
                    << "too many values: '" << line.substr(b, e - b).c_str()
                    << "' follows the last of ncols x nrows = " << nx_
                    << " x " << ny_ << " = " << n << " values"
                    << exit(FatalIOError);
            }
            // A value out of range is refused whatever v was left at
            if
            (
                kind != parsed::outOfRange
             && (std::isnan(v) || (hasNoData && v == noData))
            )
            {
                v = std::numeric_limits<double>::quiet_NaN();
            }
            else if
            (
                kind == parsed::outOfRange
             || !(std::abs(v) <= maxMagnitude_)
            )
            {
                FatalIOErrorInFunction(is)
                    << "value '" << line.substr(b, e - b).c_str() << "' (row "
                    << count/nx_ + 1 << ", column " << count % nx_ + 1
                    << ") is out of range; allowed: a finite number"
                    << boundText().c_str() << ", and for missing data nan or"
                    << " the header's NODATA_value"
                    << (hasNoData ? " (" + exactText(noData) + ")" : "").c_str()
                    << exit(FatalIOError);
            }
            const label r = count/nx_;
            values_[count - r*nx_ + nx_*(ny_ - 1 - r)] = v;
            ++count;
        }
    }
    if (count < n)
    {
        FatalIOErrorInFunction(is)
            << "too few values: found " << count << ", expected ncols x"
            << " nrows = " << nx_ << " x " << ny_ << " = " << n
            << exit(FatalIOError);
    }
}


void Foam::terrainRaster::readGeoTiff()
{
    geoTiffCodec::image img;
    geoTiffCodec::New()->read(file_, img);

    const double* gt = img.transform;
    if (!img.hasTransform)
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file_)
            << "the GeoTIFF " << file_ << " has no geotransform; expected a"
            << " georeferenced raster"
            << exit(FatalIOError);
    }
    if (gt[2] != 0 || gt[4] != 0 || !(gt[1] > 0) || !(gt[5] != 0))
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file_)
            << "the geotransform of the GeoTIFF " << file_ << " ("
            << gt[0] << ' ' << gt[1] << ' ' << gt[2] << ' ' << gt[3] << ' '
            << gt[4] << ' ' << gt[5] << ") is rotated or degenerate;"
            << " allowed: pixel width > 0, pixel height != 0 and zero"
            << " rotation terms"
            << exit(FatalIOError);
    }
    if (img.nBands < 1)
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file_)
            << "the GeoTIFF " << file_ << " has no raster band"
            << exit(FatalIOError);
    }

    nx_ = img.nx;
    ny_ = img.ny;
    dx_ = gt[1];
    dy_ = std::abs(gt[5]);
    projection_ = img.projection;

    // The geotransform locates the outer corner of pixel (0, 0); rows are
    // north to south when the pixel height is negative
    const bool northUp = gt[5] < 0;
    mapOrigin_.x() = gt[0] + dx_/2;
    mapOrigin_.y() = (northUp ? gt[3] + ny_*gt[5] : gt[3]) + dy_/2;
    const bool hasNoData = img.hasNoData;
    const double noData = img.noData;

    values_.setSize(label(nx_)*ny_);
    for (label r = 0; r < ny_; ++r)
    {
        const label j = northUp ? ny_ - 1 - r : r;
        std::copy_n
        (
            img.values.data() + size_t(nx_)*r, nx_, values_.data() + nx_*j
        );
    }

    // NaN is NODATA whether or not declared (GIS exports mark missing data
    // with it); inf and values beyond the bound are refused by their cell
    for (label k = 0; k < values_.size(); ++k)
    {
        scalar& v = values_[k];
        if (std::isnan(v) || (hasNoData && v == noData))
        {
            v = std::numeric_limits<double>::quiet_NaN();
        }
        else if (!(std::abs(v) <= maxMagnitude_))
        {
            const label i = k % nx_;
            const label j = k/nx_;
            FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file_)
                << "the value " << exactText(v).c_str() << " of the GeoTIFF "
                << file_ << " at row " << (northUp ? ny_ - j : j + 1)
                << ", column "
                << i + 1 << " (row 1 = first in the file), map coordinates ("
                << exactText(mapOrigin_.x() + i*dx_).c_str() << ' '
                << exactText(mapOrigin_.y() + j*dy_).c_str() << ") is out of"
                << " range; allowed: a finite number" << boundText().c_str()
                << ", and for missing data NaN or the band's NODATA value"
                << (hasNoData ? " (" + exactText(noData) + ")" : "").c_str()
                << exit(FatalIOError);
        }
    }
}


std::string Foam::terrainRaster::boundText() const
{
    if (maxMagnitude_ == noBound)
    {
        return "";
    }
    char text[48];
    std::snprintf(text, sizeof(text), " with |value| <= %.12g", maxMagnitude_);
    return text;
}


void Foam::terrainRaster::setGeometry()
{
    rdx_ = 1/dx_;
    rdy_ = 1/dy_;
    x0_ = mapOrigin_.x() - offset_.x();
    y0_ = mapOrigin_.y() - offset_.y();
}


Foam::label Foam::terrainRaster::updateRange()
{
    label nInvalid = 0;
    minValue_ = std::numeric_limits<double>::infinity();
    maxValue_ = -minValue_;
    for (const scalar v : values_)
    {
        if (std::isfinite(v))
        {
            minValue_ = std::min(minValue_, v);
            maxValue_ = std::max(maxValue_, v);
        }
        else
        {
            ++nInvalid;
        }
    }
    return nInvalid;
}


void Foam::terrainRaster::applyNoDataPolicy(const noDataPolicy policy)
{
    nNoData_ = updateRange();
    if (nNoData_ == values_.size())
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file_)
            << "the raster " << file_ << " has no valid value: all "
            << nNoData_ << " cells are NODATA, NaN or inf"
            << exit(FatalIOError);
    }
    if (nNoData_ == 0)
    {
        return;
    }

    if (policy == noDataPolicy::zero)
    {
        for (scalar& v : values_)
        {
            v = std::isfinite(v) ? v : 0;
        }
        minValue_ = min(minValue_, scalar(0));
        maxValue_ = max(maxValue_, scalar(0));
        Info<< "terrainRaster: read " << nNoData_ << " NODATA cells of "
            << file_ << " as 0" << endl;
        return;
    }

    if (policy == noDataPolicy::fail)
    {
        // The first in file order: rows north to south
        label k = 0;
        while (std::isfinite(values_[(ny_ - 1 - k/nx_)*nx_ + k % nx_]))
        {
            ++k;
        }
        const label r = k/nx_;
        const label i = k % nx_;
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file_)
            << "the raster " << file_ << " has " << nNoData_
            << " NODATA cells (NODATA_value, NaN or inf); the first is at"
            << " row " << r + 1 << ", column " << i + 1 << " (row 1 = north)"
            << ", map coordinates ("
            << exactText(mapOrigin_.x() + i*dx_).c_str() << ' '
            << exactText(mapOrigin_.y() + (ny_ - 1 - r)*dy_).c_str() << ")."
            << " Allowed: a raster without NODATA, or the keyword noData"
            << " (allowed values: fail, 'fill') set to 'fill' beside the"
            << " raster's file name in the dictionary, to fill them from their"
            << " neighbours"
            << exit(FatalIOError);
    }

    fillNoData();
    Info<< "terrainRaster: filled " << nNoData_ << " NODATA cells of "
        << file_ << " from their valid neighbours" << endl;
}


void Foam::terrainRaster::fillNoData()
{
    std::vector<label> todo, next;
    for (label k = 0; k < values_.size(); ++k)
    {
        if (!std::isfinite(values_[k]))
        {
            todo.push_back(k);
        }
    }

    // Layer by layer from the valid data: each sweep fills the cells that
    // touch valid (or already filled) ones with their average, and applies
    // the layer after the sweep so that the result is order-independent
    std::vector<std::pair<label, scalar>> layer;
    while (!todo.empty())
    {
        layer.clear();
        next.clear();
        for (const label k : todo)
        {
            const label i = k % nx_;
            const label j = k/nx_;
            scalar sum = 0;
            label n = 0;
            for (label jj = max(j - 1, 0); jj <= min(j + 1, ny_ - 1); ++jj)
            {
                for (label ii = max(i - 1, 0); ii <= min(i + 1, nx_ - 1); ++ii)
                {
                    const scalar v = values_[ii + nx_*jj];
                    if (std::isfinite(v))
                    {
                        sum += v;
                        ++n;
                    }
                }
            }
            if (n)
            {
                layer.emplace_back(k, sum/n);
            }
            else
            {
                next.push_back(k);
            }
        }
        for (const auto& kv : layer)
        {
            values_[kv.first] = kv.second;
        }
        todo.swap(next);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::terrainRaster::terrainRaster
(
    const fileName& file,
    const noDataPolicy policy,
    const scalar maxMagnitude
)
:
    file_(file),
    nx_(0),
    ny_(0),
    dx_(1),
    dy_(1),
    mapOrigin_(Zero),
    offset_(Zero),
    x0_(0),
    y0_(0),
    rdx_(1),
    rdy_(1),
    values_(),
    nNoData_(0),
    projection_(),
    minValue_(0),
    maxValue_(0),
    maxMagnitude_(maxMagnitude)
{
    file_.expand();
    if (!isFile(file_))
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file_)
            << "cannot find the raster file " << file_ << "; expected an"
            << " ESRI ASCII grid (.asc) or a GeoTIFF (.tif, .tiff)"
            << exit(FatalIOError);
    }

    std::string ext(file_.ext());
    std::transform
    (
        ext.begin(), ext.end(), ext.begin(),
        [](unsigned char c) { return std::tolower(c); }
    );
    if (ext != "asc" && ext != "tif" && ext != "tiff")
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file_)
            << "unknown raster file extension '." << file_.ext() << "' of "
            << file_ << "; allowed: .asc (ESRI ASCII grid), .tif or .tiff"
            << " (GeoTIFF)"
            << exit(FatalIOError);
    }

    // Read with the traps masked: a NaN, an inf or an overflow in the file
    // is a value to refuse (or NODATA), not a SIGFPE inside GDAL or here
    {
        fpTrapsHeld masked;
        if (ext == "asc")
        {
            readAsc();
        }
        else
        {
            readGeoTiff();
        }
        setGeometry();
        applyNoDataPolicy(policy);
    }
}


Foam::terrainRaster::terrainRaster
(
    const vector2D& origin,
    const scalar dx,
    const scalar dy,
    const label nx,
    const label ny,
    const UList<scalar>& values,
    const vector2D& offset,
    const string& projection
)
:
    file_(),
    nx_(nx),
    ny_(ny),
    dx_(dx),
    dy_(dy),
    mapOrigin_(origin + offset),
    offset_(offset),
    x0_(0),
    y0_(0),
    rdx_(1),
    rdy_(1),
    values_(values),
    nNoData_(0),
    projection_(projection),
    minValue_(0),
    maxValue_(0),
    maxMagnitude_(noBound)
{
    if
    (
        !(nx > 0 && ny > 0 && dx > 0 && dy > 0)
     || values.size() != nx*ny
    )
    {
        FatalErrorInFunction
            << "invalid raster: nx = " << nx << ", ny = " << ny << ", dx = "
            << dx << ", dy = " << dy << " and " << values.size()
            << " values; allowed: nx, ny >= 1, dx, dy > 0 and nx*ny values"
            << exit(FatalError);
    }
    setGeometry();
    nNoData_ = updateRange();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::boundBox Foam::terrainRaster::bounds() const
{
    return boundBox
    (
        point(x(0), y(0), minValue_),
        point(x(nx_ - 1), y(ny_ - 1), maxValue_)
    );
}


Foam::boundBox Foam::terrainRaster::cellBounds() const
{
    return boundBox
    (
        point(x(0) - dx_/2, y(0) - dy_/2, 0),
        point(x(nx_ - 1) + dx_/2, y(ny_ - 1) + dy_/2, 0)
    );
}


Foam::scalar Foam::terrainRaster::highestOver
(
    const scalar x0,
    const scalar x1,
    const scalar y0,
    const scalar y1
) const
{
    // In sample units as evaluate computes them (monotone in x: every point
    // of the rectangle lies in [s0, s1]), Z is bilinear between whole
    // sample lines (and constant beyond the hull), so on each piece of the
    // rectangle between them it is highest at a corner of the piece
    DynamicList<scalar> s, t;
    sampleBreaks((x0 - x0_)*rdx_, (x1 - x0_)*rdx_, nx_, s);
    sampleBreaks((y0 - y0_)*rdy_, (y1 - y0_)*rdy_, ny_, t);
    scalar highest = -std::numeric_limits<scalar>::infinity();
    for (const scalar tb : t)
    {
        for (const scalar sb : s)
        {
            scalar Z, dZds, dZdt;
            evaluateUnits(sb, tb, Z, dZds, dZdt);
            highest = std::max(highest, Z);
        }
    }

    // The rounding of a bilinear sum: a few ulps of the largest sample of
    // the cells (a piece's corner and a point inside it are computed in
    // different cells where it is a sample line)
    // (The first sample of the cell evaluate takes at a break point)
    const auto cell = [](scalar at, const label n)
    {
        scalar unused;
        return clampedCell(at, unused, n);
    };
    scalar magnitude = 0;
    const label i1 = min(cell(s.last(), nx_) + 1, nx_ - 1);
    const label j1 = min(cell(t.last(), ny_) + 1, ny_ - 1);
    for (label j = cell(t.first(), ny_); j <= j1; ++j)
    {
        for (label i = cell(s.first(), nx_); i <= i1; ++i)
        {
            magnitude = std::max(magnitude, std::abs(values_[i + nx_*j]));
        }
    }
    return highest + 64*std::numeric_limits<scalar>::epsilon()*magnitude;
}


void Foam::terrainRaster::setOffset(const vector2D& offset)
{
    offset_ = offset;
    setGeometry();
}


void Foam::terrainRaster::appendRow(const label j, std::string& text) const
{
    char buf[32];
    for (label i = 0; i < nx_; ++i)
    {
        const scalar v = values_[i + nx_*j];
        if (i)
        {
            text += ' ';
        }
        if (v == 0 && !std::signbit(v))
        {
            // Most of a hazard map: to_chars' text, without the call
            text += '0';
            continue;
        }
        const auto res = std::to_chars
        (
            buf, buf + sizeof(buf), std::isfinite(v) ? v : writtenNoData
        );
        text.append(buf, res.ptr);
    }
    text += '\n';
}


void Foam::terrainRaster::writeAsc(const fileName& file) const
{
    mkDir(file.path());
    OFstream os(file);
    if (!os.good())
    {
        FatalIOErrorInFunction(os)
            << "cannot write the ESRI ASCII grid " << file
            << exit(FatalIOError);
    }
    std::ostream& out = os.stdStream();

    const vector2D ll(mapLowerLeft());
    out << "ncols        " << nx_ << '\n'
        << "nrows        " << ny_ << '\n'
        << "xllcorner    " << exactText(ll.x()) << '\n'
        << "yllcorner    " << exactText(ll.y()) << '\n';
    if (dx_ == dy_)
    {
        out << "cellsize     " << exactText(dx_) << '\n';
    }
    else
    {
        out << "dx           " << exactText(dx_) << '\n'
            << "dy           " << exactText(dy_) << '\n';
    }
    out << "NODATA_value " << exactText(writtenNoData) << '\n';

    // Rows from the north, formatted in parallel by blocks and written in
    // order (the same text as one thread's): a hazard map's rasters were a
    // third of a large run-out's last write. Blocks of a few rows, taken
    // as threads come free (a dry row costs a character a value, a wet
    // one a conversion), in batches of about 65,000 values, which bound
    // the text held
    const label rowsPerBlock = 8;
    const label blocksPerBatch =
        std::max(label(1), (1 << 16)/(rowsPerBlock*std::max(nx_, label(1))));
    const label nBlocks = (ny_ + rowsPerBlock - 1)/rowsPerBlock;
    std::vector<std::string> text(std::min(nBlocks, blocksPerBatch));
    for (label first = 0; first < nBlocks; first += blocksPerBatch)
    {
        const label n = std::min(blocksPerBatch, nBlocks - first);
        #pragma omp parallel for schedule(dynamic)
        for (label b = 0; b < n; ++b)
        {
            std::string& t = text[b];
            t.clear();
            const label r0 = (first + b)*rowsPerBlock;
            const label r1 = std::min(ny_, r0 + rowsPerBlock);
            for (label r = r0; r < r1; ++r)
            {
                appendRow(ny_ - 1 - r, t);
            }
        }
        for (label b = 0; b < n; ++b)
        {
            out.write(text[b].data(), text[b].size());
        }
    }
    out.flush();
    if (!out.good())
    {
        FatalIOErrorInFunction(os)
            << "cannot write the ESRI ASCII grid " << file
            << exit(FatalIOError);
    }
}


void Foam::terrainRaster::writeGeoTiff
(
    const fileName& file,
    const sampleType type
) const
{
    fpTrapsHeld masked;
    mkDir(file.path());

    // The outer corner of the north-west pixel, rows north to south
    geoTiffCodec::image img;
    img.nx = nx_;
    img.ny = ny_;
    const vector2D ll(mapLowerLeft());
    const double gt[6] = {ll.x(), dx_, 0, ll.y() + ny_*dy_, 0, -dy_};
    std::copy(gt, gt + 6, img.transform);
    img.hasTransform = true;
    img.nBands = 1;
    img.projection = projection_;
    img.values.resize(size_t(nx_)*ny_);
    for (label r = 0; r < ny_; ++r)
    {
        const scalar* v = values_.cdata() + nx_*(ny_ - 1 - r);
        double* row = img.values.data() + size_t(nx_)*r;
        for (label i = 0; i < nx_; ++i)
        {
            row[i] = std::isfinite(v[i]) ? v[i] : writtenNoData;
        }
    }
    geoTiffCodec::New()->write
    (
        file, img, type == sampleType::float64, writtenNoData
    );
}


// ************************************************************************* //
