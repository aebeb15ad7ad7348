#!/usr/bin/env python3
"""Least stabilisation that keeps the first backward-Euler step of the 1-D column monotone.

    python3 tools/first_step_threshold.py [--elements N]

Linear 1-D consolidation (Terzaghi's column, small strain) on N equal elements of length h,
P2 displacement u, P1 pressure p, x from the fixed, impermeable bottom (x = 0) to the drained
top (x = N h), H_A = lambda + 2 mu, permeability k, c = k H_A, r = c dt / h^2:

    momentum  int f' (H_A u' - p) dx + int f' (c_e/dt) (u' - u_n') dx = -q f(top)
    mass      int g (u' - u_n')/dt dx + int k g' p' dx + int (beta/dt) g' (p' - p_n') dx = 0

f (P2, f = 0 at the bottom) and g (P1, g = 0 at the top) are the test functions; c_e is the
GLS coefficient (the paper's c_e = h^2/(4k): tau_GLS = c_e/dt = h^2/(4 k dt)) and beta the flux
perturbation's (Aguilar et al.: beta = k tau = h^2/(4 H_A)). One backward-Euler step of size dt
is taken from rest (u_n = 0, p_n = 0) with the compressive traction q applied in the step, as
the project's backward Euler does for a step load (`cases/verification/oscillation/`).
Element integrals use 3-point Gauss quadrature (exact: every integrand is at most quadratic).

Writing c_e = gamma h^2/(4k) and beta = b h^2/H_A, the script measures the overshoot
max_j p_j/q - 1 over the vertices and whether the profile is monotone (q >= p_j, p
non-decreasing with depth), bisects for the least gamma and the least b that make the step
monotone, and prints a Markdown table against the closed forms of docs/formulation.md:

    rho(s)    = -(1 - 6 s) / (sqrt(3 (1 + 12 s)) + 2 + 6 s)    (p_j - q ~ rho^(distance from top))
    overshoot = max(0, -rho(r)),   gamma_min = max(0, 2/3 - 4 r),   b_min = max(0, 1/6 - r)

(the stabilised steps are the unstabilised one at s = r + gamma/4 and s = r + b). It also
prints the first step's top settlement: unstabilised against the exact semi-infinite value
2 sqrt(c dt/pi) q/H_A, and with the paper's coefficients (gamma = 1, b = 1/4) against the
unstabilised step; and the flux perturbation's overshoot when the step starts
instead from the nodal undrained state (p_n = q, 0 at the drained vertex).
"""
import argparse
import math

import numpy as np

H_A = 1.0      # MPa
K = 1e-3       # mm^4/(N s)
H_ELEM = 0.1   # mm
Q = 1e-4       # MPa
TOL = 1e-12    # relative tolerance of the monotonicity test


def element_matrices(h):
    """Integrals over one element (local P2 order: bottom vertex, midside, top vertex; P1: the
    two vertices): A = int N_a' N_b', G = int N_a' M_b, D = int M_a' M_b'."""
    xi, w = np.polynomial.legendre.leggauss(3)
    s, w = 0.5 * (xi + 1.0), 0.5 * w * h                 # points on [0, 1], weights in x
    dn = np.array([4 * s - 3, 4 - 8 * s, 4 * s - 1]) / h  # P2 derivatives d/dx
    m = np.array([1 - s, s])                             # P1 values
    dm = np.array([[-1.0], [1.0]]) / h * np.ones_like(s)
    A = (dn * w) @ dn.T
    G = (dn * w) @ m.T
    D = (dm * w) @ dm.T
    return A, G, D


def first_step(n, r, gamma=0.0, b=0.0, p_start=None):
    """Vertex pressures p_0 (bottom) .. p_n (top) after one backward-Euler step."""
    dt = r * H_ELEM**2 / (K * H_A)
    c_e = gamma * H_ELEM**2 / (4 * K)
    beta = b * H_ELEM**2 / H_A
    A, G, D = element_matrices(H_ELEM)
    nu, np_ = 2 * n + 1, n + 1
    Kuu = np.zeros((nu, nu))
    Gup = np.zeros((nu, np_))
    Dpp = np.zeros((np_, np_))
    for e in range(n):
        iu = [2 * e, 2 * e + 1, 2 * e + 2]
        ip = [e, e + 1]
        Kuu[np.ix_(iu, iu)] += (H_A + c_e / dt) * A
        Gup[np.ix_(iu, ip)] += G
        Dpp[np.ix_(ip, ip)] += D
    p_n = np.zeros(np_) if p_start is None else p_start
    rhs = np.zeros(nu + np_)
    rhs[nu - 1] = -Q                                     # traction -q at the top node
    rhs[nu:] = (beta / dt) * Dpp.dot(p_n)             # the flux perturbation's p_n' term
    S = np.block([[Kuu, -Gup], [Gup.T / dt, (K + beta / dt) * Dpp]])
    free = np.r_[1:nu, nu:nu + np_ - 1]                  # u = 0 at the bottom, p = 0 at the top
    y = np.zeros(nu + np_)
    y[free] = np.linalg.solve(S[np.ix_(free, free)], rhs[free])
    return y[nu:]


def overshoot(p):
    return p.max() / Q - 1.0


def monotone(p):
    """No vertex above q and p non-decreasing from the drained top downwards."""
    from_top = p[::-1] / Q
    return overshoot(p) <= TOL and np.all(np.diff(from_top) >= -TOL)


def least(n, r, key, hi):
    """Least coefficient (gamma or b, by name) that makes the first step monotone."""
    if monotone(first_step(n, r, **{key: 0.0})):
        return 0.0
    while not monotone(first_step(n, r, **{key: hi})):
        hi *= 2.0
    lo = 0.0
    while hi - lo > 1e-12:
        mid = 0.5 * (lo + hi)
        if monotone(first_step(n, r, **{key: mid})):
            hi = mid
        else:
            lo = mid
    return hi


def rho(s):
    """Decaying root of the condensed vertex scheme at effective r = s."""
    return -(1 - 6 * s) / (math.sqrt(3 * (1 + 12 * s)) + 2 + 6 * s)


def settlement(n, r, gamma=0.0, b=0.0):
    """Top displacement (positive downwards) after the step: the integral of the strain
    (p - q)/(H_A + c_e/dt), which the momentum rows give exactly at every point."""
    p = first_step(n, r, gamma=gamma, b=b)
    h_eff = H_A * (1 + gamma / (4 * r))
    return -H_ELEM * np.sum(0.5 * (p[1:] + p[:-1]) - Q) / h_eff


def fmt(x):
    return "0" if x <= TOL else ("%.4g" % x)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--elements", type=int, default=40, help="elements in the column")
    n = ap.parse_args().elements
    rs = [1e-3, 3e-3, 1e-2, 3e-2, 0.05, 0.1, 0.15, 1 / 6, 0.2, 0.3]
    names = {1 / 6: "1/6"}

    print("N = %d elements; first backward-Euler step from rest, step load q.\n" % n)
    print("| r | overshoot, none | −ρ(r) | γ_min | 2/3 − 4r | b_min | 1/6 − r "
          "| settlement: none / exact | GLS γ=1 / none | flux b=1/4 / none |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    worst = 0.0
    for r in rs:
        p = first_step(n, r)
        g_num, b_num = least(n, r, "gamma", 1.0), least(n, r, "b", 0.25)
        g_cf, b_cf = max(0.0, 2 / 3 - 4 * r), max(0.0, 1 / 6 - r)
        worst = max(worst, abs(g_num - g_cf), abs(b_num - b_cf))
        w0 = settlement(n, r)
        w_exact = 2 * math.sqrt(r / math.pi) * Q * H_ELEM / H_A
        print("| %s | %s | %s | %.6f | %.6f | %.6f | %.6f | %.3f | %.3f | %.3f |" % (
            names.get(r, "%g" % r), fmt(max(0.0, overshoot(p))), fmt(max(0.0, -rho(r))),
            g_num, g_cf, b_num, b_cf, w0 / w_exact,
            settlement(n, r, gamma=1.0) / w0, settlement(n, r, b=0.25) / w0))
    print("\nlargest |numerical − closed form| of γ_min, b_min: %.1e" % worst)

    print("\nFlux perturbation b = 1/4 started from the nodal undrained state "
          "(p_n = q, 0 at the drained vertex):\n")
    print("| r | overshoot | (1 − 6r)/(√(3(1+12s)) + 2 + 6s), s = r + b |")
    print("|---|---|---|")
    p_und = np.full(n + 1, Q)
    p_und[-1] = 0.0
    for r in [1e-3, 1e-2, 0.1]:
        s = r + 0.25
        p = first_step(n, r, b=0.25, p_start=p_und)
        print("| %g | %.4g | %.4g |" % (r, overshoot(p),
                                         (1 - 6 * r) / (math.sqrt(3 * (1 + 12 * s)) + 2 + 6 * s)))


if __name__ == "__main__":
    main()
