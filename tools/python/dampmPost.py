"""dampm post-processing helpers: read OpenFOAM point fields, clouds and mesh
points (ASCII or binary), the suite's postProcessing .dat time series, and the analytic
solutions the tutorials and tests compare against.

Used by the tutorials' plot scripts, tests/cases and benchmarks; put
$DAMPM_PROJECT_DIR/tools/python on sys.path (etc/bashrc sets
DAMPM_PROJECT_DIR).
"""
import json
import math
import os
import re

import numpy as np


def _list_after(text, start):
    """Numbers of the first OpenFOAM list at or after start: 'N ( ... )', or
    'N{value}' (a uniform list, as OpenFOAM writes it)."""
    m = re.compile(r"(\d+)\s*([({])").search(text, start)
    if not m:
        raise ValueError("no list found")
    n = int(m.group(1))
    if m.group(2) == "{":
        end = text.index("}", m.end())
        value = np.array(text[m.end():end].replace("(", " ").replace(")", " ").split(), dtype=float)
        return n, np.tile(value, n)
    body_start = m.end()
    depth, i = 1, body_start
    while depth:
        c = text[i]
        depth += (c == "(") - (c == ")")
        i += 1
    body = text[body_start:i - 1].replace("(", " ").replace(")", " ")
    values = np.array(body.split(), dtype=float)
    return n, values


# Components of an OpenFOAM field class's element, most specific first
_COMPONENTS = (("symmtensor2d", 3), ("tensor2d", 4), ("symmtensor", 6), ("sphericaltensor", 1),
               ("tensor", 9), ("vector2d", 2), ("vector", 3), ("label", 1), ("scalar", 1))


class _FoamFile:
    """An OpenFOAM file: its FoamFile header and its bytes. Binary files
    (format binary) hold their lists as blocks of bytes, 'N(' then N
    elements then ')' (an empty one: '0' alone), with labels and scalars of
    the header's arch."""

    def __init__(self, path):
        self.path = path
        with open(path, "rb") as f:
            self.data = f.read()
        self.body = self.data.index(b"}") + 1
        header = self.data[:self.body].decode("latin-1")
        m = re.search(r"format\s+(\w+)\s*;", header)
        self.format = m.group(1) if m else None
        self.binary = self.format == "binary"
        m = re.search(r"class\s+([\w<>]+)\s*;", header)
        self.cls = m.group(1).lower() if m else ""
        arch = re.search(r"label\s*=\s*(\d+)", header)
        self.label = "<i%d" % (int(arch.group(1)) // 8) if arch else "<i4"

    def components(self):
        for name, k in _COMPONENTS:
            if name in self.cls:
                return k
        raise ValueError("%s: no field type in class %s" % (self.path, self.cls))

    def positions(self, start):
        """A binary Cloud<passiveParticle>'s positions: N x 4, the position
        and the cell (as ASCII lists them), from '(' the position and the
        cell ')' per particle."""
        m = re.compile(rb"(\d+)\s*\(").search(self.data, start)
        n = int(m.group(1))
        record = np.dtype([("open", "S1"), ("x", "<f8", 3), ("cell", self.label), ("close", "S1"),
                           ("nl", "S1")])
        first = self.data.index(b"(", m.end()) if n else m.end()
        r = np.frombuffer(self.data, dtype=record, count=n, offset=first)
        return n, np.column_stack([r["x"], r["cell"]]).ravel()

    def list_after(self, start):
        """Element count and values (flat) of the first list at or after
        the byte offset start."""
        if not self.binary:
            text = self.data.decode("latin-1")
            return _list_after(text, start)
        if self.cls.startswith("cloud<"):
            return self.positions(start)
        m = re.compile(rb"(\d+)\s*([({]?)").search(self.data, start)
        if not m:
            raise ValueError("%s: no list found" % self.path)
        n = int(m.group(1))
        if n == 0:
            # An empty binary list is its size alone
            return 0, np.empty(0)
        if not m.group(2):
            raise ValueError("%s: no list found" % self.path)
        if m.group(2) == b"{":
            return _list_after(self.data[m.start():].decode("latin-1"), 0)
        k = self.components()
        dtype = self.label if "label" in self.cls else "<f8"
        values = np.frombuffer(self.data, dtype=dtype, count=n * k, offset=m.end())
        return n, values.astype(float)


def file_format(path):
    """The format an OpenFOAM file's header names: 'ascii' or 'binary'
    (None: none named)."""
    return _FoamFile(path).format


def read_points(case):
    """Mesh points (N x 3) of constant/polyMesh/points."""
    f = _FoamFile(os.path.join(case, "constant", "polyMesh", "points"))
    n, v = f.list_after(f.body)
    return v.reshape(n, 3)


def processors(case):
    """The processor directories of a decomposed case, in rank order."""
    found = []
    for d in os.listdir(case):
        if d.startswith("processor") and d[9:].isdigit():
            found.append((int(d[9:]), d))
    return [os.path.join(case, d) for _, d in sorted(found)]


def read_field(case, time, name, region="", cloud=None):
    """Internal values of a field (scalar: N, vector: N x 3) written at a
    time, ASCII or binary; cloud names a lagrangian cloud. A uniform field
    is an error (callers know the size). The cloud of a decomposed case
    (no cloud at the case's own time) is every processor's in rank order."""
    parts = [case, str(time)]
    if cloud:
        parts += ["lagrangian", cloud]
        if not os.path.isdir(os.path.join(*parts)) and processors(case):
            pieces = [read_field(p, time, name, cloud=cloud) for p in processors(case)]
            held = [v for v in pieces if v.size]
            return np.concatenate(held) if held else pieces[0]
    path = os.path.join(*parts, name)
    f = _FoamFile(path)
    key = f.data.find(b"internalField", f.body)
    start = key if key >= 0 else f.body
    if key >= 0 and b"nonuniform" not in f.data[key:key + 60]:
        raise ValueError("%s is uniform" % path)
    n, v = f.list_after(start)
    if n == 0:
        return v
    return v.reshape(n, -1) if v.size != n else v


def read_dat(path):
    """A postProcessing .dat file: dict column name -> numpy array."""
    header = None
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                header = line[1:].split()
            elif line.strip():
                rows.append([float(x) for x in line.split()])
    data = np.array(rows, dtype=float).reshape(len(rows), len(header))
    return {name: data[:, k] for k, name in enumerate(header)}


def read_series(d, file):
    """A time series across restarts: the .dat files d/<startTime>/file
    (d a postProcessing/<name> folder) joined in time order, each start
    time's rows replacing those of an earlier one from its first row's time
    on (a run restarted from a time directory goes on from there; without
    rows, from the start time)."""
    starts = sorted((s for s in os.listdir(d)
                     if os.path.isfile(os.path.join(d, s, file))), key=float)
    if not starts:
        raise FileNotFoundError("no %s under %s" % (file, d))
    parts = [read_dat(os.path.join(d, s, file)) for s in starts]
    names = list(parts[0])
    for s, p in zip(starts, parts):
        if list(p) != names:
            raise ValueError("%s/%s/%s: columns %s, not %s"
                             % (d, s, file, list(p), names))
    kept = [parts[-1]]
    for p, s in zip(parts[-2::-1], starts[:0:-1]):
        later = kept[0]["time"]
        if len(later):
            t = later[0]
            n = int(np.searchsorted(p["time"], t - 1e-12 * max(1.0, abs(t))))
        else:
            t = float(s)
            n = int(np.searchsorted(p["time"], t + 1e-12 * max(1.0, abs(t)), side="right"))
        kept.insert(0, {c: p[c][:n] for c in names})
    return {c: np.concatenate([p[c] for p in kept]) for c in names}


def dat_value(path, key):
    """The number a '# key value ...' comment line of a .dat file states
    (e.g. the width of a barrier's force.dat); None without one."""
    with open(path) as f:
        for line in f:
            if not line.startswith("#"):
                break
            words = line[1:].split()
            if len(words) > 1 and words[0] == key:
                return float(words[1])
    return None


def step_integral(t, F, a, b):
    """Integral over [a, b] of a per-step series (a solver's .dat: t the
    steps' end times, F the value of the step ending there, held over it)."""
    t0 = np.concatenate(([t[0] - (t[1] - t[0])], t[:-1]))
    return float(np.sum(F * (np.clip(t, a, b) - np.clip(t0, a, b))))


def running_mean(t, F, w):
    """Means of a per-step series over windows of length w, sampled every
    1e-4 s: the windows' end times and their means."""
    tu = np.arange(t[0], t[-1], 1e-4)
    k = int(round(w / 1e-4))
    if len(tu) <= k:
        return tu[:1], np.zeros(1)
    Fu = F[np.minimum(np.searchsorted(t, tu), len(t) - 1)]
    c = np.concatenate(([0.0], np.cumsum(Fu)))
    return tu[k - 1:], (c[k:] - c[:-k]) / k


def times(case):
    """Numeric time directories of a case, in time order."""
    found = []
    for d in os.listdir(case):
        try:
            found.append((float(d), d))
        except ValueError:
            pass
    return [d for _, d in sorted(found)]


def latest_time(case):
    """Largest numeric time directory of a case."""
    return times(case)[-1]


def files_below(d):
    """The files below directory d, as paths relative to it, sorted."""
    return sorted(os.path.relpath(os.path.join(r, f), d) for r, _, fs in os.walk(d) for f in fs)


def differing_files(a, b, files=None):
    """The files (paths relative to a and b; by default every file below a)
    that are not byte for byte the same in directory b, or are missing there."""
    def content(path):
        try:
            with open(path, "rb") as f:
                return f.read()
        except OSError:
            return None
    differing = []
    for f in files_below(a) if files is None else files:
        other = content(os.path.join(b, f))
        if other is None or other != content(os.path.join(a, f)):
            differing.append(f)
    return differing


def structure_points(case, name):
    """Node positions (N x 3) of a flexible barrier at its last write: the
    legacy VTK file listed last in VTK/<name>.vtk.series."""
    with open(os.path.join(case, "VTK", name + ".vtk.series")) as f:
        last = json.load(f)["files"][-1]["name"]
    with open(os.path.join(case, "VTK", last)) as f:
        words = f.read().split()
    i = words.index("POINTS")
    n = int(words[i + 1])
    return np.array(words[i + 3:i + 3 + 3 * n], dtype=float).reshape(n, 3)


def cloud_positions(case, time, cloud):
    """Particle positions (N x 3) of a lagrangian cloud written at a time."""
    return read_field(case, time, "positions", cloud=cloud).reshape(-1, 4)[:, :3]


def elastic_cloud_energy(case, time, E, nu, h, cloud="mpm3dCloud"):
    """Kinetic and elastic energy [J] of a linear elastic cloud written at a
    time, and its x momentum [kg m/s]: kinetic with APIC's affine part
    (quadratic B-splines: D = h^2/4, h the cell size), elastic from sigma
    and V."""
    def field(name):
        return np.array(read_field(case, time, name, cloud=cloud))
    m, u, C = field("m"), field("U"), field("gradU")
    s, V = field("sigma"), field("V")
    xx, xy, xz, yy, yz, zz = s.T
    w = ((1 + nu) * (xx**2 + yy**2 + zz**2 + 2 * (xy**2 + xz**2 + yz**2))
         - nu * (xx + yy + zz)**2) / (2 * E)
    kinetic = 0.5 * (m * (u**2).sum(axis=1)).sum() \
        + 0.5 * (m * h**2 / 4 * (C**2).sum(axis=1)).sum()
    return kinetic + (w * V).sum(), (m * u[:, 0]).sum()


def membrane_energy_budget(case, E, nu, h, barrier="net", cloud="mpm3dCloud"):
    """The energy budget of a linear elastic cloud against a flexible
    barrier, at the cloud's write times: the times, the energy the bodies
    and the contact hold (the cloud's kinetic and elastic, the structure's
    strain and kinetic, the contact's push, and the flow's potential energy
    gained since the start), the contact's dissipation so far [J], and the
    cloud's x momentum [kg m/s]. barrier None: a rigid barrier (the cloud's
    energy alone)."""
    t = [s for s in times(case)
         if os.path.isdir(os.path.join(case, s, "lagrangian", cloud))]
    net = barrier and read_dat(os.path.join(case, "postProcessing", barrier, "0", "membrane.dat"))
    flow = read_dat(os.path.join(case, "postProcessing", "mpm3dFoam", "0", "energy.dat"))
    held, dissipated, px = [], [], []
    for s in t:
        eb, p = elastic_cloud_energy(case, s, E, nu, h, cloud)
        em, d, ep = 0.0, 0.0, 0.0
        if float(s) > 0 and net:
            j = np.argmin(abs(net["time"] - float(s)))
            em = net["strainEnergy"][j] + net["kineticEnergy"][j] + net["contactEnergy"][j]
            d = net["contactDissipation"][j]
        if float(s) > 0:
            k = np.argmin(abs(flow["time"] - float(s)))
            ep = flow["potentialEnergy"][k] - flow["potentialEnergy"][0]
        held.append(eb + em + ep)
        dissipated.append(d)
        px.append(p)
    return (np.array([float(s) for s in t]), np.array(held), np.array(dissipated),
            np.array(px))


def ritter(x, t, h0, x0, g=9.81):
    """Ritter's dry-bed dam break: height and velocity at x (array), time t,
    reservoir of depth h0 for x < x0."""
    c0 = math.sqrt(g * h0)
    xi = (np.asarray(x, dtype=float) - x0) / t
    h = np.where(xi <= -c0, h0, (2 * c0 - xi) ** 2 / (9 * g))
    u = np.where(xi <= -c0, 0.0, 2.0 / 3.0 * (c0 + xi))
    beyond = xi >= 2 * c0
    h = np.where(beyond, 0.0, h)
    u = np.where(beyond, 0.0, u)
    return h, u


def mangeney(x, t, h0, a, gp):
    """Mangeney et al. (2000) dam break on an incline: material at x < 0,
    net acceleration a, pressure gravity gp; height and velocity."""
    c0 = math.sqrt(gp * h0)
    x = np.asarray(x, dtype=float)
    xa = -c0 * t + 0.5 * a * t * t
    xb = 2 * c0 * t + 0.5 * a * t * t
    h = np.where(x <= xa, h0, (2 * c0 - x / t + 0.5 * a * t) ** 2 / (9 * gp))
    u = np.where(x <= xa, a * t, 2.0 / 3.0 * (c0 + x / t + a * t))
    h = np.where(x >= xb, 0.0, h)
    u = np.where(x >= xb, 0.0, u)
    return h, u


def read_asc(path):
    """An ESRI ASCII grid: dict with x (ncols), y (nrows, south to north)
    sample-centre coordinates, z (nrows x ncols, row 0 south; NODATA as NaN)
    and offset (the lower-left corner)."""
    header = {}
    with open(path) as f:
        while True:
            pos = f.tell()
            parts = f.readline().split()
            if not parts or not parts[0][0].isalpha():
                f.seek(pos)
                break
            header[parts[0].lower()] = float(parts[1])
        z = np.array(f.read().split(), dtype=float)
    nx, ny = int(header["ncols"]), int(header["nrows"])
    d = header.get("cellsize", header.get("dx"))
    dy = header.get("cellsize", header.get("dy"))
    if "xllcorner" in header:
        x0, y0 = header["xllcorner"] + d / 2, header["yllcorner"] + dy / 2
    else:
        x0, y0 = header["xllcenter"], header["yllcenter"]
    z = z.reshape(ny, nx)[::-1]
    if "nodata_value" in header:
        z[z == header["nodata_value"]] = np.nan
    return {"x": x0 + d * np.arange(nx), "y": y0 + dy * np.arange(ny), "z": z,
            "offset": (x0 - d / 2, y0 - dy / 2)}
