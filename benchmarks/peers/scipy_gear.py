#!/usr/bin/python3
"""The torsional and bta models of geardyn written with SciPy's solve_ivp, as a user would.

Written from docs/model.md (sections 3, 5 and 6: the dimensionless equations, the dead-zone
contact law, the excitations) and nothing else of geardyn's code: the parameters are read from
the summary.json of a geardyn `response` run of the same case (the resolved case keys and the
derived model scales it reports), so that both programs integrate the same scene.

Two ways of handling the contacts, both with DOP853 or LSODA:
  * events:  every clearance crossing is a terminal solve_ivp event; the integration stops
             there, the contact mode is flipped, and it restarts with the new mode (the
             right-hand side uses the held mode, as geardyn does);
  * naive:   no events; the right-hand side takes the contact mode from the state at every
             call (what a first attempt looks like).
The Poincare points (the full state at every mesh-period boundary) and the RMS of the mean mesh
acceleration ((a_L + a_R)/2, 64 samples per period) are returned, with wall time and RHS calls.

Limits (said, not hidden): harmonic or constant mesh stiffness only (no rectangular), mesh
damping acting always (mesh_damping_mode = always), models torsional and bta.

Use from compare_geardyn_scipy.py (the benchmark driver), or alone:
    /usr/bin/python3 scipy_gear.py SUMMARY_JSON POINCARE_CSV PERIODS METHOD RTOL [events|naive]
which integrates PERIODS mesh periods from the first row of POINCARE_CSV (a geardyn
poincare.csv) and prints the Poincare points.
"""
import json
import math
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp


def _param(summary, section, key):
    return summary["case"]["parameters"][section][key]["value"]


class GearModel:
    """The dimensionless model of docs/model.md section 6 (tau = omega_n t, lengths over b_c)."""

    def __init__(self, summary):
        s = summary
        kind = s["model"]
        if kind not in ("torsional", "bta"):
            raise ValueError("scipy_gear: model %s not written (torsional and bta are)" % kind)
        if _param(s, "excitation", "stiffness") == "rectangular":
            raise ValueError("scipy_gear: rectangular stiffness not written")
        if _param(s, "damping", "mesh_damping_mode") != "always":
            raise ValueError("scipy_gear: mesh damping in contact only not written")
        der = s["derived"]["model"]
        geo = s["derived"]["geometry"]
        km = der["mesh_stiffness_n_per_m"]           # k_m, one half, along the normal
        mn = der["normal_equivalent_mass_kg"]        # m_n = m_e / cos^2(beta_b)
        self.omega_n = math.sqrt(km / mn)
        self.bc = _param(s, "solver", "characteristic_length_um") * 1e-6
        z1 = _param(s, "gear", "teeth_pinion")
        n = _param(s, "operating", "speed_rpm")
        self.Omega = 2 * math.pi * z1 * n / 60 / self.omega_n
        self.period = 2 * math.pi / self.Omega
        F0 = der["static_mesh_force_n"] / (km * self.bc)  # static normal load of one half, dimensionless
        zeta = _param(s, "damping", "mesh_damping_ratio")
        b = 0.5 * _param(s, "clearance", "backlash_um") * 1e-6 / self.bc
        # excitation of each half: stiffness harmonics and transmission error
        if _param(s, "excitation", "stiffness") == "harmonic":
            self.a = list(_param(s, "excitation", "stiffness_harmonics"))
            ph = list(_param(s, "excitation", "stiffness_phases_deg"))
            self.phi = [math.radians(ph[j]) if j < len(ph) else 0.0 for j in range(len(self.a))]
        else:
            self.a, self.phi = [], []
        on = 1.0 if _param(s, "scene", "error_excitation") else 0.0
        self.e_m = on * _param(s, "excitation", "ste_mean_um") * 1e-6 / self.bc
        self.e_r = on * _param(s, "excitation", "ste_amplitude_um") * 1e-6 / self.bc
        self.e_phi = math.radians(_param(s, "excitation", "ste_phase_deg"))
        cscale = 1.0 / (mn * self.omega_n)
        # clearances: (weights {dof: w}, half gap, stiffness, damping, mesh index or -1)
        self.clear = []
        if kind == "torsional":
            self.ndof = 1
            self.mass = np.array([2.0])
            self.F = np.array([2.0 * F0])
            self.K = np.zeros((1, 1))
            self.C = np.zeros((1, 1))
            self.half_phase = [0.0]
            self.clear.append(({0: 1.0}, b, 2.0, 4.0 * zeta, 0))
            self.meshes = [0]
        else:
            self.ndof = 10
            bb = math.radians(geo["base_helix_angle_deg"])
            cb = math.cos(bb)
            sb = math.sin(bb) if _param(s, "scene", "axial_coupling") else 0.0
            m1 = _param(s, "gear", "pinion_mass_kg")
            m2 = _param(s, "gear", "gear_mass_kg")
            k1y = _param(s, "support", "radial_stiffness_pinion_n_per_m")
            k2y = _param(s, "support", "radial_stiffness_gear_n_per_m")
            k1z = _param(s, "support", "axial_stiffness_pinion_n_per_m")
            k2z = _param(s, "support", "axial_stiffness_gear_n_per_m")
            k1s = _param(s, "support", "shaft_stiffness_pinion_n_per_m")
            k2s = _param(s, "support", "shaft_stiffness_gear_n_per_m")
            zs = _param(s, "damping", "support_damping_ratio")
            zsh = _param(s, "damping", "shaft_damping_ratio")
            eps = 0.5 * _param(s, "clearance", "bearing_clearance_um") * 1e-6 / self.bc
            clr = _param(s, "scene", "bearing_clearance")
            self.half_phase = [0.0, math.radians(_param(s, "excitation", "half_phase_deg"))]
            self.mass = np.zeros(10)
            self.F = np.zeros(10)
            self.K = np.zeros((10, 10))
            self.C = np.zeros((10, 10))

            def spring(i, j, k, c):
                self.K[i, i] += k
                self.C[i, i] += c
                if j >= 0:
                    self.K[j, j] += k
                    self.K[i, j] -= k
                    self.K[j, i] -= k
                    self.C[j, j] += c
                    self.C[i, j] -= c
                    self.C[j, i] -= c

            self.meshes = []
            bearings = []
            for h in range(2):
                o = 5 * h
                sig = 1.0 if h == 0 else -1.0
                self.mass[o:o + 5] = [m1 / mn, m1 / mn, m2 / mn, m2 / mn, 1.0]
                self.F[o + 4] = F0
                self.meshes.append(len(self.clear))
                self.clear.append(({o + 0: cb, o + 2: -cb, o + 4: 1.0, o + 1: sig * sb, o + 3: -sig * sb},
                                   b, 1.0, 2.0 * zeta, h))
                for body in range(2):
                    i = o + 2 * body
                    k, m = (k2y, m2) if body else (k1y, m1)
                    cy = 2.0 * zs * math.sqrt(k * m) * cscale
                    if clr:
                        bearings.append(({i: 1.0}, eps, k / km, 0.0, -1))
                        self.C[i, i] += cy          # bearing damping acts always
                    else:
                        spring(i, -1, k / km, cy)
                spring(o + 1, -1, k1z / km, 2.0 * zs * math.sqrt(k1z * m1) * cscale)
                spring(o + 3, -1, k2z / km, 2.0 * zs * math.sqrt(k2z * m2) * cscale)
            spring(1, 6, k1s / km, 2.0 * zsh * math.sqrt(k1s * m1 / 2.0) * cscale)
            spring(3, 8, k2s / km, 2.0 * zsh * math.sqrt(k2s * m2 / 2.0) * cscale)
            # geardyn's order: mesh-L, bearings of L, mesh-R, bearings of R
            self.clear = [self.clear[0]] + bearings[:2] + [self.clear[1]] + bearings[2:]
            self.meshes = [0, 3] if clr else [0, 1]
        self.n = 2 * self.ndof
        self.Minv = 1.0 / self.mass
        # weights as dense vectors for speed
        self.W = []
        for w, h, k, c, mesh in self.clear:
            v = np.zeros(self.ndof)
            for i, x in w.items():
                v[i] += x
            self.W.append((v, h, k, c, mesh))

    # excitation of mesh j at tau: stiffness factor, error and its two derivatives
    def excitation(self, j, t):
        ph = self.Omega * t + self.half_phase[j]
        s = 1.0
        for h, (a, p) in enumerate(zip(self.a, self.phi)):
            s += a * math.cos((h + 1) * ph + p)
        arg = ph + self.e_phi
        e = self.e_m + self.e_r * math.sin(arg)
        ed = self.e_r * self.Omega * math.cos(arg)
        edd = -self.e_r * self.Omega ** 2 * math.sin(arg)
        return s, e, ed, edd

    def coords(self, t, y):
        """Clearance coordinates and rates."""
        x, v = y[:self.ndof], y[self.ndof:]
        out = []
        for w, h, k, c, mesh in self.W:
            xc, vc = w @ x, w @ v
            if mesh >= 0:
                _, e, ed, _ = self.excitation(mesh, t)
                xc -= e
                vc -= ed
            out.append((xc, vc))
        return out

    @staticmethod
    def mode_of(x, h):
        return 1 if x > h else (-1 if x < -h else 0)

    def rhs(self, t, y, modes=None):
        """ydot with the held modes (events) or the modes of the state (modes None: naive)."""
        x, v = y[:self.ndof], y[self.ndof:]
        a = self.F - self.K @ x - self.C @ v
        kf = {}
        for idx, (w, h, k, c, mesh) in enumerate(self.W):
            xc, vc = w @ x, w @ v
            s = 1.0
            if mesh >= 0:
                if mesh not in kf:
                    kf[mesh] = self.excitation(mesh, t)
                s, e, ed, _ = kf[mesh]
                xc -= e
                vc -= ed
            m = self.mode_of(xc, h) if modes is None else modes[idx]
            f = c * vc
            if m > 0:
                f += k * s * (xc - h)
            elif m < 0:
                f += k * s * (xc + h)
            a = a - w * f
        return np.concatenate((v, a * self.Minv))

    def mean_accel(self, t, y, ydot):
        """(a_L + a_R)/2 of the mesh deflections (dimensionless)."""
        acc = []
        for mi in self.meshes:
            w, h, k, c, mesh = self.W[mi]
            _, _, _, edd = self.excitation(mesh, t)
            acc.append(w @ ydot[self.ndof:] - edd)
        if len(acc) == 1:
            acc.append(acc[0])
        return 0.5 * (acc[0] + acc[1])

    def accel_scale(self):
        return self.bc * self.omega_n ** 2


def _event_functions(model, modes):
    """Terminal events of the held modes: in contact only the way out, in the gap both ways in."""
    evs = []
    for idx, (w, h, k, c, mesh) in enumerate(model.W):
        m = modes[idx]

        def g(t, y, idx=idx, off=-h):
            return model.coords(t, y)[idx][0] + off

        def gl(t, y, idx=idx, off=h):
            return model.coords(t, y)[idx][0] + off

        if m == 1:
            g.terminal, g.direction = True, -1
            evs.append((g, idx, 0))
        elif m == -1:
            gl.terminal, gl.direction = True, 1
            evs.append((gl, idx, 0))
        else:
            g.terminal, g.direction = True, 1
            gl.terminal, gl.direction = True, -1
            evs.append((g, idx, 1))
            evs.append((gl, idx, -1))
    return evs


def simulate(model, y0, periods, method, rtol, atol, with_events=True, samples=64):
    """Integrate `periods` mesh periods from y0: Poincare points, RMS acceleration, cost."""
    T = model.period
    y = np.array(y0, dtype=float)
    modes = [model.mode_of(xc, w[1]) for (xc, _), w in zip(model.coords(0.0, y), model.W)]
    pts = [y.copy()]
    nfev = 0
    events = 0
    sum2, count = 0.0, 0
    t0w = time.perf_counter()
    if not with_events:
        ts = np.arange(periods * samples + 1) * (T / samples)
        sol = solve_ivp(lambda t, yy: model.rhs(t, yy), (0.0, periods * T), y, method=method, rtol=rtol, atol=atol,
                        t_eval=ts, max_step=0.1 * T if method == "DOP853" else np.inf)
        if sol.status != 0:
            raise RuntimeError(sol.message)
        nfev = sol.nfev
        for i in range(1, periods + 1):
            pts.append(sol.y[:, i * samples].copy())
        for i in range(periods * samples):
            yi = sol.y[:, i]
            a = model.mean_accel(ts[i], yi, model.rhs(ts[i], yi))
            sum2 += a * a
            count += 1
        wall = time.perf_counter() - t0w
        return np.array(pts), math.sqrt(sum2 / count) * model.accel_scale(), nfev, None, wall
    t = 0.0
    for k in range(periods):
        t_end = (k + 1) * T
        while True:
            ts = [t_s for t_s in (np.arange(samples) * (T / samples) + k * T) if t <= t_s < t_end]
            evs = _event_functions(model, modes)
            sol = solve_ivp(lambda tt, yy: model.rhs(tt, yy, modes), (t, t_end), y, method=method, rtol=rtol,
                            atol=atol, events=[e[0] for e in evs], t_eval=ts + [t_end],
                            max_step=0.1 * T if method == "DOP853" else np.inf)
            if sol.status < 0:
                raise RuntimeError(sol.message)
            nfev += sol.nfev
            for i, t_s in enumerate(sol.t):
                if t_s >= t_end:
                    break
                yi = sol.y[:, i]
                a = model.mean_accel(t_s, yi, model.rhs(t_s, yi, modes))
                sum2 += a * a
                count += 1
            if sol.status == 1:    # an event: flip the mode and restart from the event state
                hits = [j for j, te in enumerate(sol.t_events) if len(te)]
                i = min(hits, key=lambda j: sol.t_events[j][0])
                t = float(sol.t_events[i][0])
                y = np.array(sol.y_events[i][0])
                flipped = set()
                for j in hits:     # the two halves of a herringbone cross together
                    if abs(sol.t_events[j][0] - t) <= 1e-12 * (1 + abs(t)):
                        _, idx, to = evs[j]
                        modes[idx] = to if modes[idx] == 0 else 0
                        flipped.add(idx)
                        events += 1
                # another clearance that lies past its boundary, or on it and crossing it now (the
                # other half of a symmetric pair, a rounding later), would never be seen crossing
                # after the restart: switch it now
                for idx, (xc, vc) in enumerate(model.coords(t, y)):
                    h = model.W[idx][1]
                    m0 = modes[idx]
                    past = h - xc if m0 > 0 else xc + h if m0 < 0 else abs(xc) - h
                    going = -vc if m0 > 0 else vc if m0 < 0 else (vc if xc > 0 else -vc)
                    if idx in flipped or not (past > 1e-9 * (1 + h) or (past > -1e-9 * (1 + h) and going > 0)):
                        continue
                    if m0 == 0:
                        modes[idx] = 1 if xc > 0 else -1
                    else:
                        modes[idx] = 0 if h > 0 else -m0
                    events += 1
                continue
            y = sol.y[:, -1].copy()
            t = t_end
            break
        pts.append(y.copy())
    wall = time.perf_counter() - t0w
    return np.array(pts), math.sqrt(sum2 / count) * model.accel_scale(), nfev, events, wall


def poincare_error(a, b):
    """max |a - b| / (1 + max |b|) per state variable (geardyn's gd_workprec_poincare_error)."""
    sc = 1.0 + np.max(np.abs(b), axis=0)
    return float(np.max(np.abs(a - b) / sc))


def read_poincare(path):
    """State columns of a geardyn poincare.csv (full precision of the file)."""
    rows = []
    with open(path) as f:
        head = f.readline().strip().split(",")
        first = max(head.index(c) for c in ("lambda_dot_L", "lambda_dot_R") if c in head) + 1
        for line in f:
            v = line.strip().split(",")
            rows.append([float(x) for x in v[first:]])
    return np.array(rows)


if __name__ == "__main__":
    if len(sys.argv) < 6:
        print(__doc__)
        sys.exit(2)
    summ = json.load(open(sys.argv[1]))
    P = read_poincare(sys.argv[2])
    model = GearModel(summ)
    mode = sys.argv[6] if len(sys.argv) > 6 else "events"
    pts, rms, nfev, events, wall = simulate(model, P[0], int(sys.argv[3]), sys.argv[4], float(sys.argv[5]),
                                            float(sys.argv[5]) / 100, mode == "events")
    print("rms %.9g m/s^2, %d RHS calls, %s events, %.3f s" % (rms, nfev, events, wall))
    n = min(len(pts), len(P))
    print("Poincare difference to the csv over %d points: %.3g" % (n, poincare_error(pts[:n], P[:n])))
