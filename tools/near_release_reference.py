#!/usr/bin/env python3
"""References for tests/near_release.rs: pushes just below the release push (issue 38).

Regenerate with `python3 tools/near_release_reference.py` (and `--past` for the flat time of a
start past the release push); needs mpmath (mpmath 1.3.0 was used).
The printed Rust rows are pasted into tests/sim/near_release/pushes.rs unchanged.

Each start is (g, l, theta0 or phi0 = pi/2 - theta0, rate0), every input the exact binary64 value
the Rust test passes.  With omega^2 = 3g/(4l) (exact from the binary64 g and l) and
D = omega^2 cos(theta0) - rate0^2 (the wall force's factor at the start), the energy integral
(eq. (10) of the note, generalised to a moving start) gives the separation

    sin^2(theta_s/2) = sin^2(theta0/2) + D/(6 omega^2),    thetadot_s^2 = omega^2 cos(theta_s),

evaluated at 120 digits (no acos near 1).  The time is the quadrature
t_s = int dtheta / thetadot over [theta0, theta_s] of tools/exact_reference.py (tanh-sinh on
geometrically refined pieces of the offset theta - theta0), cross-checked against that script's
Legendre form; the script stops if they disagree beyond 1e-28 relative.  Near the floor the
angle is printed as phi_s = pi/2 - theta_s; the travel theta_s - theta0 is printed too.
"""
import math
import struct
import sys

import mpmath as mp

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from exact_reference import time_legendre, time_quad  # noqa: E402

mp.mp.dps = 40


def f64_below(x):
    """The largest binary64 strictly below the real x > 0."""
    y = float(x)
    while mp.mpf(y) >= x:
        y = struct.unpack("<d", struct.pack("<q", struct.unpack("<q", struct.pack("<d", y))[0] - 1))[0]
    return y


def start(g, l, theta0, phi0):
    w2 = 3 * mp.mpf(g) / (4 * mp.mpf(l))
    if phi0 is None:
        th0 = mp.mpf(theta0)
    else:
        th0 = mp.pi / 2 - mp.mpf(phi0)
    return w2, th0


def separation(g, l, theta0, phi0, rate0):
    with mp.workdps(120):
        w2, th0 = start(g, l, theta0, phi0)
        r0 = mp.mpf(rate0)
        d = w2 * mp.cos(th0) - r0**2
        if d <= 0:
            sys.exit(f"not below the release push: D = {d}")
        ss2 = mp.sin(th0 / 2) ** 2 + d / (6 * w2)
        th_s = 2 * mp.asin(mp.sqrt(ss2))
        rate_s = mp.sqrt(w2 * mp.cos(th_s))
        angle = th_s if phi0 is None else mp.pi / 2 - th_s
        travel = th_s - th0
    t_s = time_quad(th0, r0, w2, th_s)
    t_l = time_legendre(th0, r0, w2, th_s)
    if abs(t_s - t_l) > mp.mpf(10) ** (-28) * t_s:
        sys.exit(f"quadrature and Legendre form disagree: {t_s} vs {t_l}")
    return d, angle, travel, t_s, rate_s


def cases():
    unit_omega = math.sqrt(0.75)
    rows = []
    # From upright on the unit ladder: the pushes.
    for label, w in [
        ("Ω(1 − 1e-9)", unit_omega * (1 - 1e-9)),
        ("Ω(1 − 1e-12)", unit_omega * (1 - 1e-12)),
        ("Ω(1 − 1e-14)", unit_omega * (1 - 1e-14)),
        ("one ulp below fl(Ω)", 0.8660254037844385),
        ("fl(Ω), the largest f64 below Ω", unit_omega),
    ]:
        rows.append((label, 1.0, 1.0, 0.0, None, w))
    # In SI: the scaling to the unit ladder must not round the margin away.
    g, l = 9.81, 0.7
    w2, _ = start(g, l, 0.0, None)
    rows.append(("SI g=9.81 l=0.7, largest f64 below Ω", g, l, 0.0, None, f64_below(mp.sqrt(w2))))
    rows.append(("SI g=9.81 l=0.7, Ω(1 − 1e-12)", g, l, 0.0, None,
                 math.sqrt(3 * g / (4 * l)) * (1 - 1e-12)))
    # Leaning starts: the largest f64 push below Ω √cos θ0.
    for theta0 in [1e-6, 0.3, 1.2]:
        w2, th0 = start(1.0, 1.0, theta0, None)
        rows.append((f"θ0 = {theta0}, largest f64 below Ω √cos θ0", 1.0, 1.0, theta0, None,
                     f64_below(mp.sqrt(w2 * mp.cos(th0)))))
    w2, th0 = start(1.0, 1.0, 0.3, None)
    rows.append(("θ0 = 0.3, Ω √cos θ0 (1 − 1e-12)", 1.0, 1.0, 0.3, None,
                 float(mp.sqrt(w2 * mp.cos(th0))) * (1 - 1e-12)))
    # Near the floor, given as phi0.
    w2, th0 = start(1.0, 1.0, None, 1e-12)
    rows.append(("φ0 = 1e-12, largest f64 below Ω √sin φ0", 1.0, 1.0, None, 1e-12,
                 f64_below(mp.sqrt(w2 * mp.cos(th0)))))
    return rows


def past_flat_time(rate0):
    """Flat time of the floor phase from upright at rate0 >= omega (g = l = 1): the top leaves
    at once; Xdot = rate0 and the energy are kept, so
    thetadot^2 = (rate0^2/3 + 2 (1 - cos theta)) / (sin^2 theta + 1/3)."""
    w = mp.mpf(rate0)

    def f(th):
        return 1 / mp.sqrt((w**2 / 3 + 2 * (1 - mp.cos(th))) / (mp.sin(th) ** 2 + mp.mpf(1) / 3))

    t = mp.quad(f, [0, mp.pi / 4, mp.pi / 2])
    with mp.workdps(60):
        t2 = mp.quad(f, [0, mp.pi / 8, mp.pi / 4, 3 * mp.pi / 8, mp.pi / 2])
    if abs(t - t2) > mp.mpf(10) ** (-30) * t:
        sys.exit(f"quadratures disagree: {t} vs {t2}")
    return t


def main():
    if "--past" in sys.argv:
        print("// flat time from upright at rate0 = 0.9 (g = l = 1), past the release push")
        print(mp.nstr(past_flat_time(0.9), 25))
        return
    print("// (g, l, theta0, phi0 (0: theta0 given), rate0, D, theta_s (phi_s if phi0),\n//  theta_s - theta0, t_s, rate_s)")
    for label, g, l, theta0, phi0, w in cases():
        d, angle, travel, t_s, rate_s = separation(g, l, theta0, phi0, w)
        ins = [g, l, theta0 if theta0 is not None else 0.0, phi0 if phi0 is not None else 0.0, w]
        row = ", ".join(repr(float(x)) for x in ins)
        row += ", " + ", ".join(mp.nstr(v, 25) for v in (d, angle, travel, t_s, rate_s))
        print(f"    // {label}")
        print(f"    [{row}],")


if __name__ == "__main__":
    main()
