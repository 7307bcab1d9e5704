#!/usr/bin/env python3
"""Time SciPy's solve_ivp (DOP853, RK45, Radau) on the ladder's wall phase, for comparison with
`cargo bench --bench integrators` and `ladder work-precision`. Optional: needs numpy and scipy.

Separation is a terminal event on g = w2 cos(theta) - theta_dot^2 (direction -1), as in the crate.
The reference is the closed form cos(theta_s) = (2 w2 cos(theta0) + rate0^2) / (3 w2) for the
angle; the time is reported against the crate's `ladder simulate --json` value given with --ref.

Usage: python3 bench/scipy_peer.py [theta0] [rate0]
"""
import math
import sys
import time

try:
    import numpy as np
    from scipy.integrate import solve_ivp
except ImportError:
    print("scipy_peer: numpy/scipy not installed; nothing to do")
    sys.exit(0)

W2 = 3 * 9.81 / 4.0


def rhs(_t, y):
    return [y[1], W2 * math.sin(y[0])]


def event(_t, y):
    return W2 * math.cos(y[0]) - y[1] ** 2


event.terminal = True
event.direction = -1


def main():
    theta0 = float(sys.argv[1]) if len(sys.argv) > 1 else 0.3
    rate0 = float(sys.argv[2]) if len(sys.argv) > 2 else 0.0
    angle = math.acos((2 * W2 * math.cos(theta0) + rate0**2) / (3 * W2))
    print(f"theta0={theta0} rate0={rate0} exact separation angle {angle!r}")
    print("method  rtol      angle_err   seconds_median  nfev")
    for method in ["DOP853", "RK45", "Radau"]:
        for k in range(4, 15, 2):
            tol = 10.0**-k
            times = []
            for _ in range(7):
                t0 = time.perf_counter()
                sol = solve_ivp(rhs, (0, 100), [theta0, rate0], method=method, rtol=tol,
                                atol=tol, events=event, dense_output=False)
                times.append(time.perf_counter() - t0)
            if sol.t_events[0].size == 0:
                continue
            a = sol.y_events[0][0][0]
            print(f"{method:7} {tol:.0e}  {abs(a - angle) / angle:.2e}    {np.median(times):.3e}      {sol.nfev}")


if __name__ == "__main__":
    main()
