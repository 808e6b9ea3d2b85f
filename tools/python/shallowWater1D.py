"""A small 1D finite-volume shallow-water solver: the reference the
dampmFoam tests compare run-out fronts against.

Equations: the shallow-water equations in horizontal coordinates, the
paper's eq. 1 (Fois, Katili et al., n.d.) as dampmFoam solves it with
slopeCorrection false, frictionless and inviscid (h vertical depth [m], u
horizontal velocity [m/s], Z(x) the bed [m], g gravity [m/s^2]):

    h_t + (h u)_x = 0
    (h u)_t + (h u^2 + g h^2/2)_x = -g h Z_x

Scheme (all standard; the references are the papers, no code was copied):
- cell averages of h and q = h u on a uniform grid, bed Z sampled at the
  cell centres;
- second order in space: MUSCL reconstruction of h, of the free surface
  eta = h + Z and of u, with the minmod limiter (a wet/dry front then keeps
  h >= 0 at the faces); Z at the faces is eta - h;
- hydrostatic reconstruction at every face (Audusse, Bouchut, Bristeau,
  Klein & Perthame, 2004): Z* = max(Z_L, Z_R), h*_L,R = max(0, eta_L,R - Z*),
  with the second-order correction of the bed source inside each cell. It
  keeps a lake at rest exactly, over a bed step too, and h >= 0;
- HLL flux (Harten, Lax & van Leer, 1983) with Toro's (2001) wave speeds,
  those of the dry-bed Riemann problem when a side is dry (thinner than
  hDry = 1e-6 m): S_L = u_L - c_L, S_R = u_L + 2 c_L when h_R = 0, and
  symmetrically;
- velocity from q with the desingularisation of Kurganov & Petrova (2007),
  u = 2 h q/(h^2 + max(h^2, hDry^2)), and q = h u after each stage: films
  thinner than hDry move with the flow instead of dividing by zero;
- SSP Runge-Kutta 2 (Heun) in time, the step cfl dx/S with S the fastest
  face wave of the step (a dry front's u + 2c included), cfl = 0.45;
- sides: 'wall' (reflecting: mirrored state) or 'open' (transmissive).

Verification (tests/cases/reference/shallowWater1D; verify() prints the
first two): Ritter's dry dam break on a flat bed (first-order L1
convergence, the 1 % front within 1 % at 1600 cells), a lake at rest over a
bed step against a dry slope (at rest to 1e-14 m/s), and the front arrivals
of test 5.2 converging to the stored reference slidingToWallArrivals.

References
Audusse, E., Bouchut, F., Bristeau, M.-O., Klein, R., & Perthame, B. (2004).
A fast and stable well-balanced scheme with hydrostatic reconstruction for
shallow water flows. SIAM Journal on Scientific Computing, 25(6), 2050-2065.
Harten, A., Lax, P. D., & van Leer, B. (1983). On upstream differencing and
Godunov-type schemes for hyperbolic conservation laws. SIAM Review, 25(1),
35-61.
Kurganov, A., & Petrova, G. (2007). A second-order well-balanced positivity
preserving central-upwind scheme for the Saint-Venant system.
Communications in Mathematical Sciences, 5(1), 133-160.
Ritter, A. (1892). Die Fortpflanzung der Wasserwellen. Zeitschrift des
Vereines Deutscher Ingenieure, 36(33), 947-954.
Toro, E. F. (2001). Shock-capturing methods for free-surface shallow flows.
Wiley.
"""
import math

import numpy as np


def _minmod(a, b):
    return np.where(a * b > 0, np.sign(a) * np.minimum(np.abs(a), np.abs(b)), 0.0)


class ShallowWater1D:
    """Cells of width dx over [x0, x1]; bed(x) gives Z; sides ('wall' or
    'open') at x0 and x1."""

    def __init__(self, x0, x1, nCells, bed, h0, u0=None, g=9.81, sides=("wall", "open"),
                 cfl=0.45, hDry=1e-6):
        self.g, self.cfl, self.hDry = g, cfl, hDry
        self.dx = (x1 - x0) / nCells
        self.x = x0 + (np.arange(nCells) + 0.5) * self.dx
        self.Z = np.asarray(bed(self.x), dtype=float)
        self.h = np.maximum(np.asarray(h0(self.x), dtype=float), 0.0)
        self.q = self.h * (np.asarray(u0(self.x), dtype=float) if u0 else 0.0)
        self.sides = sides
        self.t = 0.0

    def _consistent(self, h, q):
        """h >= 0 (round-off only, the step keeps it positive) and q = h u
        with the desingularised u (Kurganov & Petrova, 2007)"""
        h = np.maximum(h, 0.0)
        return h, h * self.velocity(h, q)

    def velocity(self, h, q):
        eps = self.hDry
        return 2 * h * q / (h * h + np.maximum(h * h, eps * eps))

    def _ghosts(self, a, kind):
        """a extended by two ghost cells each side: kind 'scalar' (mirrored
        or copied), 'odd' (velocity: reflected at walls)."""
        left = a[1::-1].copy()
        right = a[:-3:-1].copy()
        if kind == "odd" and self.sides[0] == "wall":
            left = -left
        if kind == "odd" and self.sides[1] == "wall":
            right = -right
        return np.concatenate([left, a, right])

    def _rhs(self, h, q):
        g = self.g
        u = self.velocity(h, q)
        H = self._ghosts(h, "scalar")
        U = self._ghosts(u, "odd")
        Zg = self._ghosts(self.Z, "scalar")
        E = H + Zg
        # Limited slopes of h, eta and u, cells -1 .. n (one ghost each side)
        dH = _minmod(H[1:-1] - H[:-2], H[2:] - H[1:-1])
        dE = _minmod(E[1:-1] - E[:-2], E[2:] - E[1:-1])
        dU = _minmod(U[1:-1] - U[:-2], U[2:] - U[1:-1])
        Hc, Ec, Uc = H[1:-1], E[1:-1], U[1:-1]
        # Face values of each cell: minus (left face) and plus (right face).
        # h from its own slope keeps h >= 0; eta's slope sets Z at the faces
        hM, hP = Hc - 0.5 * dH, Hc + 0.5 * dH
        eM, eP = Ec - 0.5 * dE, Ec + 0.5 * dE
        uM, uP = Uc - 0.5 * dU, Uc + 0.5 * dU
        zM, zP = eM - hM, eP - hP
        # Face i+1/2 between cell i (plus side) and i+1 (minus side), for the
        # n + 1 faces of the n cells
        hL, hR = hP[:-1], hM[1:]
        uL, uR = uP[:-1], uM[1:]
        zL, zR = zP[:-1], zM[1:]
        zStar = np.maximum(zL, zR)
        hLs = np.maximum(0.0, hL + zL - zStar)
        hRs = np.maximum(0.0, hR + zR - zStar)
        F, smax = self._hll(hLs, uL, hRs, uR)
        # Hydrostatic reconstruction source (Audusse et al., 2004), with the
        # centred second-order term inside each cell
        n = h.size
        s = np.zeros(n)
        # Cell i: its right face is face i + 1 (its own state there hL[i+1]),
        # its left face is face i (its own state there hR[i])
        s -= 0.5 * g * (hL[1:] ** 2 - hLs[1:] ** 2)
        s += 0.5 * g * (hR[:-1] ** 2 - hRs[:-1] ** 2)
        hMi, hPi = hM[1:-1], hP[1:-1]
        zMi, zPi = zM[1:-1], zP[1:-1]
        s -= 0.5 * g * (hMi + hPi) * (zPi - zMi)
        dh = -(F[0][1:] - F[0][:-1]) / self.dx
        dq = -(F[1][1:] - F[1][:-1]) / self.dx + s / self.dx
        # The fastest wave of the face problems bounds the step (a dry front
        # runs at u + 2c, faster than |u| + c of any cell)
        speed = max(smax, np.max(np.abs(u) + np.sqrt(g * h)))
        return dh, dq, speed

    def _hll(self, hL, uL, hR, uR):
        g = self.g
        # A side thinner than hDry is dry: no flux of its own, and the dry
        # front's speeds (Toro's bore speed into a film diverges as the
        # film thins)
        dryL, dryR = hL <= self.hDry, hR <= self.hDry
        hL, hR = np.where(dryL, 0.0, hL), np.where(dryR, 0.0, hR)
        uL, uR = np.where(dryL, 0.0, uL), np.where(dryR, 0.0, uR)
        cL, cR = np.sqrt(g * hL), np.sqrt(g * hR)
        # Wave speeds (Toro, 2001): two-rarefaction estimate of the star
        # depth for wet sides; exact dry-front speeds for a dry side
        hs = np.maximum(0.0, 0.5 * (cL + cR) + 0.25 * (uL - uR)) ** 2 / g
        hLw, hRw = np.where(dryL, 1.0, hL), np.where(dryR, 1.0, hR)
        qL = np.where(hs > hLw, np.sqrt(0.5 * (hs + hLw) * hs) / hLw, 1.0)
        qR = np.where(hs > hRw, np.sqrt(0.5 * (hs + hRw) * hs) / hRw, 1.0)
        SL = np.where(dryL, uR - 2 * cR, np.where(dryR, uL - cL, uL - cL * qL))
        SR = np.where(dryR, uL + 2 * cL, np.where(dryL, uR + cR, uR + cR * qR))
        both = dryL & dryR
        SL = np.where(both, 0.0, SL)
        SR = np.where(both, 0.0, SR)
        fL = (hL * uL, hL * uL * uL + 0.5 * g * hL * hL)
        fR = (hR * uR, hR * uR * uR + 0.5 * g * hR * hR)
        UL, UR = (hL, hL * uL), (hR, hR * uR)
        out = []
        span = np.where(SR - SL > 0, SR - SL, 1.0)
        for k in range(2):
            mid = (SR * fL[k] - SL * fR[k] + SL * SR * (UR[k] - UL[k])) / span
            out.append(np.where(SL >= 0, fL[k], np.where(SR <= 0, fR[k], mid)))
        out = [np.where(both, 0.0, f) for f in out]
        return out, float(np.max(np.maximum(np.abs(SL), np.abs(SR))))

    def step(self, tMax=None):
        dh, dq, speed = self._rhs(self.h, self.q)
        dt = self.cfl * self.dx / max(speed, 1e-12)
        if tMax is not None:
            dt = min(dt, tMax - self.t)
        h1, q1 = self._consistent(self.h + dt * dh, self.q + dt * dq)
        dh2, dq2, _ = self._rhs(h1, q1)
        self.h, self.q = self._consistent(0.5 * (self.h + h1 + dt * dh2),
                                          0.5 * (self.q + q1 + dt * dq2))
        self.t += dt
        return dt

    def run(self, tEnd, monitor=None):
        """Step to tEnd; monitor(self) after every step (it may return True
        to stop)."""
        while self.t < tEnd - 1e-12:
            self.step(tEnd)
            if monitor and monitor(self):
                break

    def depthAt(self, x):
        """h at x, linear between cell centres."""
        return float(np.interp(x, self.x, self.h))

    def volume(self):
        return float(np.sum(self.h) * self.dx)


def frontPosition(x, h, depth):
    """The farthest x at which h reaches depth: linear between the last
    point at or above it and the next (-inf if none is)."""
    k = np.nonzero(h >= depth)[0]
    if k.size == 0:
        return -math.inf
    k = k.max()
    if k + 1 >= x.size:
        return float(x[-1])
    return float(x[k] + (h[k] - depth) / (h[k] - h[k + 1]) * (x[k + 1] - x[k]))


def arrivalTimes(sim, xProbe, depths, tEnd):
    """The times [s] at which the fronts of the depths [m] (frontPosition,
    between cell centres) reach xProbe, linear in time between steps; NaN
    if not reached by tEnd. The run stops when all have."""
    found = {d: math.nan for d in depths}
    prev = {d: (sim.t, frontPosition(sim.x, sim.h, d)) for d in depths}

    def monitor(s):
        for d in depths:
            if not math.isnan(found[d]):
                continue
            xNow = frontPosition(s.x, s.h, d)
            t0, x0 = prev[d]
            if xNow >= xProbe:
                found[d] = s.t if not math.isfinite(x0) or xNow <= x0 \
                    else t0 + (xProbe - x0) / (xNow - x0) * (s.t - t0)
            prev[d] = (s.t, xNow)
        return not any(math.isnan(v) for v in found.values())

    sim.run(tEnd, monitor)
    return found


def slidingToWall(nCells, g=9.81):
    """The paper's test 5.2 run-out as dampmFoam runs it
    (tutorials/coupled/slidingToWall/runOut): bed Z = 10 - x/3 for x <= 10,
    10 - 10/3 beyond; water in 1.5 <= x <= 5 up to the level 9.5 m; wall at
    x = 0, open at x = 25."""
    def bed(x):
        return np.where(x <= 10, 10 - x / 3, 10 - 10 / 3)

    def h0(x):
        return np.where((x >= 1.5) & (x <= 5), np.maximum(9.5 - bed(x), 0.0), 0.0)

    return ShallowWater1D(0.0, 25.0, nCells, bed, h0, g=g, sides=("wall", "open"))


#: The reference of tests/cases/dampmFoam/slidingToWall1D: times [s] at which
#: the 1 mm, 1 cm and 10 cm fronts of slidingToWall() reach x = 20 m,
#: Richardson-extrapolated at first order, 2 t(16000) - t(8000), from
#:     arrivalTimes(slidingToWall(n), 20.0, [1e-3, 1e-2, 1e-1], 2.9)
#: n = 8000 (3.1 mm cells): 1.8238, 1.9515, 2.7503 s; n = 16000: 1.8195,
#: 1.9509, 2.7507 s (6 and 24 minutes on one core). The 1 mm front converges
#: slowest: 0.0043 s (0.24 %) from 8000 to 16000 cells.
slidingToWallArrivals = {1e-3: 1.8152, 1e-2: 1.9503, 1e-1: 2.7511}


def ritterError(nCells, t=2.0, h0=1.0, g=9.81):
    """Ritter's dry dam break on [-20, 20] (dam at 0, flat bed, h0 for x<0):
    L1 error of h / (h0 L) at t and the error of the 1 % front position
    relative to the exact travel 1.7 c0 t."""
    sim = ShallowWater1D(-20.0, 20.0, nCells, lambda x: 0 * x, lambda x: np.where(x < 0, h0, 0.0),
                         g=g, sides=("open", "open"))
    sim.run(t)
    c0 = math.sqrt(g * h0)
    xi = sim.x / t
    he = np.where(xi <= -c0, h0, np.where(xi >= 2 * c0, 0.0, (2 * c0 - xi) ** 2 / (9 * g)))
    l1 = np.sum(np.abs(sim.h - he)) * sim.dx / (h0 * 40.0)
    k = np.nonzero(sim.h > 0.01 * h0)[0].max()
    xf = sim.x[k] + (sim.h[k] - 0.01 * h0) / (sim.h[k] - sim.h[k + 1]) * sim.dx
    return l1, (xf - 1.7 * c0 * t) / (1.7 * c0 * t), sim


def lakeAtRest(nCells, tEnd=2.0):
    """Largest speed [m/s] of a lake at rest (level 1.5 m) over a bed with a
    0.5 m step at x = 0.3 and a dry slope rising from x = 0.7 (shoreline),
    after tEnd."""
    def bed(x):
        return np.where(x < 0.3, 0.0, 0.5) + np.where(x > 0.7, 4 * (x - 0.7), 0.0)

    sim = ShallowWater1D(0.0, 1.0, nCells, bed, lambda x: np.maximum(1.5 - bed(x), 0.0),
                         sides=("wall", "wall"))
    v0 = sim.volume()
    speeds = []
    sim.run(tEnd, lambda s: speeds.append(np.max(np.abs(s.velocity(s.h, s.q)))))
    return max(speeds), abs(sim.volume() - v0) / v0


def verify():
    """Print the verification measures (used by the test
    tests/cases/reference/shallowWater1D)."""
    out = {}
    for n in (400, 800, 1600):
        l1, front, _ = ritterError(n)
        out[n] = (l1, front)
        print("Ritter, %d cells (dx = %.4g m): L1 = %.2e, 1 %% front %+.3f %%" % (n, 40.0 / n, l1, 100 * front))
    vmax, dv = lakeAtRest(200)
    print("lake at rest over a bed step and a dry shore, 200 cells, 2 s: largest speed %.2e m/s,"
          " volume change %.1e" % (vmax, dv))
    return out, vmax, dv


if __name__ == "__main__":
    verify()
