#!/usr/bin/env python3
"""Reference values for tests/sim/exact/reference.rs (phase one of the sliding ladder).

Regenerate with `python3 tools/exact_reference.py` (separation table) and
`python3 tools/exact_reference.py --jacobi` (Jacobi table); needs mpmath (`pip install mpmath`).
The printed Rust rows are pasted into `tests/sim/exact/mpmath.rs`.

Method (independent of src/sim/exact): every input is the exact binary64 value the Rust test
passes, lifted to 60 significant digits.  The separation angle comes from the note's footnote 4
generalised to a moving start, cos(theta_s) = (2/3) cos(theta0) + rate0^2 / (3 omega^2), evaluated
in high precision.  The separation time is the quadrature t = int dtheta / thetadot(theta) with
thetadot^2 = rate0^2 + 2 omega^2 (cos theta0 - cos theta) (energy, eq. (10) of the note generalised),
done with mpmath's tanh-sinh rule on geometrically refined sub-intervals; it is cross-checked
against Legendre's incomplete integral F(phi|m) (mpmath.ellipf) in the textbook pendulum form and
the script stops if the two disagree beyond 1e-28 (relative).  The mid-course angle theta(t_q) at the binary64
time t_q nearest t_s/2 is found by Newton's method on the quadrature.
"""
import math
import sys

import mpmath as mp

mp.mp.dps = 40


def energy_rate2_offset(d, th0, r0, w2):
    # thetadot^2 at theta = th0 + d: r0^2 + 2 w2 (cos th0 - cos th), with
    # cos th0 - cos th = 2 sin(d/2) sin(th0 + d/2) written without cancellation
    return r0**2 + 4 * w2 * mp.sin(d / 2) * mp.sin(th0 + d / 2)


def energy_rate2(th, th0, r0, w2):
    return energy_rate2_offset(th - th0, th0, r0, w2)


def time_quad(th0, r0, w2, th):
    """t(th) = int_{th0}^{th} dtheta / thetadot, tanh-sinh on geometrically refined pieces."""
    if th == th0:
        return mp.mpf(0)
    # integrate over the offset d = theta - th0 so that nodes crowding the endpoint stay distinct
    d = th - th0
    pts = [mp.mpf(0)] + [d * mp.mpf(10) ** (-j) for j in range(45, 0, -3)] + [d]
    f = lambda x: 1 / mp.sqrt(energy_rate2_offset(x, th0, r0, w2))
    return mp.quad(f, pts)


def time_legendre(th0, r0, w2, th):
    """Same time from F(phi|m), written in pendulum variables (independent cross-check)."""
    # m = 1 - k'^2 sits within 1e-25 of 1 near the separatrix: carry 60 extra digits
    with mp.workdps(mp.mp.dps + 60):
        return +_time_legendre(th0, r0, w2, th)


def _time_legendre(th0, r0, w2, th):
    w = mp.sqrt(w2)
    s0, c0 = mp.sin(th0 / 2), mp.cos(th0 / 2)
    rho2 = r0**2 / (4 * w2)
    a = s0**2 - rho2  # thetadot^2 = 4 w2 (sin^2(th/2) - a)
    s = mp.sin(th / 2)
    if a > 0:  # libration: turning point sin(th/2) = k'
        kp2 = a
        m = 1 - kp2

        def T(x):
            # amplitude from its tangent: asin near 1 would waste the working digits
            c = mp.sqrt(1 - x**2)
            return mp.ellipf(mp.atan(mp.sqrt(x**2 - kp2) / (mp.sqrt(kp2) * c)), m) / w

        return T(s) - T(s0)
    if a < 0:  # rotation through theta = 0
        h2 = -a
        m = 1 / (1 + h2)

        def T(x):
            c = mp.sqrt(1 - x**2)
            psi = mp.atan(x * mp.sqrt(1 + h2) / (mp.sqrt(h2) * c))
            return mp.sqrt(m) * mp.ellipf(psi, m) / w

        return T(s) - T(s0)
    # separatrix: tan(th/4) grows like exp(w t)
    return (mp.log(mp.tan(th / 4)) - mp.log(mp.tan(th0 / 4))) / w


def theta_at(th0, r0, w2, tq, th_s):
    """Newton on t(th) = tq (Legendre form, fast), bracketed in [th0, th_s]; the root is then
    confirmed by the quadrature."""
    lo, hi = th0, th_s
    th = (lo + hi) / 2
    for _ in range(200):
        g = time_legendre(th0, r0, w2, th) - tq
        if abs(g) <= mp.mpf(10) ** (-33) * tq:
            if abs(time_quad(th0, r0, w2, th) - tq) > mp.mpf(10) ** (-28) * tq:
                sys.exit("quadrature does not confirm theta(t_q)")
            return th
        if g > 0:
            hi = th
        else:
            lo = th
        nth = th - g * mp.sqrt(energy_rate2(th, th0, r0, w2))
        th = nth if lo < nth < hi else (lo + hi) / 2
    raise RuntimeError("Newton did not converge")


def case(th0f, r0f, w2f):
    th0, r0, w2 = mp.mpf(th0f), mp.mpf(r0f), mp.mpf(w2f)
    c_s = mp.mpf(2) / 3 * mp.cos(th0) + r0**2 / (3 * w2)
    if c_s >= mp.cos(th0):  # wall force already <= 0: separation at t = 0
        return th0, mp.mpf(0), r0, 0.0, th0, r0
    th_s = mp.acos(c_s)
    t_s = time_quad(th0, r0, w2, th_s)
    t_l = time_legendre(th0, r0, w2, th_s)
    if abs(t_s - t_l) > mp.mpf(10) ** (-28) * t_s:
        sys.exit(f"quadrature and Legendre form disagree: {t_s} vs {t_l}")
    rate_s = mp.sqrt(w2 * c_s)  # at separation thetadot^2 = omega^2 cos(theta_s)
    tq = float(t_s / 2)
    th_q = theta_at(th0, r0, w2, mp.mpf(tq), th_s)
    rate_q = mp.sqrt(energy_rate2(th_q, th0, r0, w2))
    return th_s, t_s, rate_s, tq, th_q, rate_q


CASES = (
    [(t, 0.0, 1.0) for t in (1e-12, 1e-8, 1e-4, 0.01, 0.1, 0.3, 0.7, 1.0, 1.4, math.pi / 2 - 1e-6)]
    + [(0.0, r, 1.0) for r in (1e-15, 1e-10, 1e-6, 1e-3, 0.1, 0.5, 0.999, 0.999999, 1.0, 1.5)]
    + [(0.3, 0.5, 1.0), (1e-6, 2e-6, 1.0), (0.5, 0.4, 1.0), (1e-6, 1e-6, 1.0)]
    + [(t, 0.0, 7.3575) for t in (1e-8, 0.3)]
    + [(0.0, r, 7.3575) for r in (1e-10, 2.0)]
    + [(0.3, 0.0, 0.25), (0.0, 1e-6, 16.0), (0.7, 0.005, 1e-4)]
)


# Jacobi functions: (k', argument, 0 = u from zero / 1 = v back from K), values at u or K - v.
JACOBI = [(0.5, 0.3, 0), (0.9, 1.2, 0), (1e-6, 3.0, 0), (1e-12, 5.0, 0), (0.3, -0.7, 0),
          (1.0, 0.7, 0), (1e-100, 100.0, 0), (1e-12, 1.1, 1), (1e-6, 0.5, 1), (0.5, 0.2, 1),
          (1e-100, 2.0, 1), (1e-12, 14.5, 1)]


def jacobi_rows():
    print("// (k', arg, from_quarter, K, sn, cn, dn), mpmath.ellipfun at m = 1 - k'^2")
    for kc, arg, quarter in JACOBI:
        with mp.workdps(mp.mp.dps + 220):  # m = 1 - 1e-200 must survive
            m = 1 - mp.mpf(kc) ** 2
            K = mp.ellipk(m)
            u = K - mp.mpf(arg) if quarter else mp.mpf(arg)
            vals = [K] + [mp.ellipfun(f, u, m=m) for f in ("sn", "cn", "dn")]
        row = f"{kc!r}, {arg!r}, {float(quarter)!r}, " + ", ".join(mp.nstr(v, 25) for v in vals)
        print(f"    [{row}],")


def main():
    if "--jacobi" in sys.argv:
        return jacobi_rows()
    print("// (theta0, rate0, omega2, sep_angle, sep_time, sep_rate, t_mid, theta_mid, rate_mid)")
    for th0f, r0f, w2f in CASES:
        vals = case(th0f, r0f, w2f)
        row = ", ".join(repr(x) for x in (th0f, r0f, w2f))
        row += ", " + ", ".join(mp.nstr(v, 25, min_fixed=1, max_fixed=0) if not isinstance(v, float)
                               else repr(v) for v in vals)
        print(f"    [{row}],")


if __name__ == "__main__":
    main()
