"""Raster files for the fault tests of the terrain and release readers: ESRI
ASCII grids with any token in any cell (0x423, 1e400, 12abc, nan, ...), and
GeoTIFFs written byte by byte (Debian's python3 has no GDAL binding) with a
NODATA value such as NaN, as GIS exports write them.

Arrays are indexed z[j, i]: i along x (east), j along y (north), j = 0 the
southern row; (x0, y0) is the lower-left corner of the raster's cells."""
import struct

import numpy as np


def ascText(z, x0, y0, cell, noData=-9999, tokens=None):
    """An ESRI ASCII grid of z (xllcorner form, rows north to south), with
    tokens {(i, j): text} written in place of those cells' values."""
    ny, nx = z.shape
    lines = ["ncols %d" % nx, "nrows %d" % ny, "xllcorner %r" % float(x0), "yllcorner %r" % float(y0),
             "cellsize %r" % float(cell)]
    if noData is not None:
        lines.append("NODATA_value %s" % noData)
    tokens = tokens or {}
    for j in reversed(range(ny)):
        lines.append(" ".join(tokens.get((i, j), repr(float(z[j, i]))) for i in range(nx)))
    return "\n".join(lines) + "\n"


def lineOf(z, i, j, noData=-9999):
    """The line number (from 1) of cell (i, j) in ascText's file."""
    return 5 + (noData is not None) + (z.shape[0] - j)


def geoTiffBytes(z, x0, y0, cell, noData=None, float64=False):
    """A north-up GeoTIFF of z (one band, uncompressed, one strip, float32 or
    float64 samples), georeferenced by ModelPixelScale and ModelTiepoint,
    with GDAL's NODATA tag (42113) when noData is given ("nan" for NaN)."""
    ny, nx = z.shape
    data = np.ascontiguousarray(np.flipud(z), dtype="<f8" if float64 else "<f4").tobytes()
    SHORT, LONG, ASCII, DOUBLE = 3, 4, 2, 12
    entries = []

    def entry(tag, kind, values):
        if kind == ASCII:
            payload = values.encode() + b"\0"
            count = len(payload)
        else:
            code = {SHORT: "H", LONG: "I", DOUBLE: "d"}[kind]
            payload = struct.pack("<%d%s" % (len(values), code), *values)
            count = len(values)
        entries.append([tag, kind, count, payload])

    entry(256, LONG, [nx])                          # ImageWidth
    entry(257, LONG, [ny])                          # ImageLength
    entry(258, SHORT, [64 if float64 else 32])      # BitsPerSample
    entry(259, SHORT, [1])                          # Compression: none
    entry(262, SHORT, [1])                          # Photometric: min is black
    entry(273, LONG, [0])                           # StripOffsets, set below
    entry(277, SHORT, [1])                          # SamplesPerPixel
    entry(278, LONG, [ny])                          # RowsPerStrip
    entry(279, LONG, [len(data)])                   # StripByteCounts
    entry(284, SHORT, [1])                          # PlanarConfiguration
    entry(339, SHORT, [3])                          # SampleFormat: IEEE float
    entry(33550, DOUBLE, [cell, cell, 0.0])         # ModelPixelScale
    entry(33922, DOUBLE, [0, 0, 0, x0, y0 + ny * cell, 0])     # ModelTiepoint
    entry(34735, SHORT, [1, 1, 0, 1, 1025, 0, 1, 1])           # PixelIsArea
    if noData is not None:
        entry(42113, ASCII, str(noData))            # GDAL_NODATA

    # Header, the directory, the values too long for it, then the samples
    start = 8 + 2 + 12 * len(entries) + 4
    extra = b""
    where = []
    for e in entries:
        if len(e[3]) > 4:
            where.append(start + len(extra))
            extra += e[3] + b"\0" * (len(e[3]) % 2)
        else:
            where.append(None)
    dataOffset = start + len(extra)
    entries[5][3] = struct.pack("<I", dataOffset)
    ifd = struct.pack("<H", len(entries))
    for e, w in zip(entries, where):
        ifd += struct.pack("<HHI", e[0], e[1], e[2])
        ifd += e[3].ljust(4, b"\0") if w is None else struct.pack("<I", w)
    ifd += struct.pack("<I", 0)
    return b"II*\0" + struct.pack("<I", 8) + ifd + extra + data
