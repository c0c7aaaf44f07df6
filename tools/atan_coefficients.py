#!/usr/bin/env python3
"""Derives the polynomial of cpp/include/circledist/detail/atan2.hpp and prints its error bound.

atan(t) = t + t z P(z), z = t^2, for |t| <= tan(pi/8): P of degree 10 interpolates
(atan(sqrt z)/sqrt z - 1)/z at the 11 Chebyshev points of [0, Z], Z a hair past tan(pi/8)^2
(the double threshold's rounding), solved at 60 digits with mpmath. Prints the coefficients,
highest degree first (the header's Horner order), rounded to double, and the largest error of
t + t z P(z) against atan(t), with the rounded coefficients in exact arithmetic, in units of
2^-52 relative to atan(t), over 3000 points of [0, tan(pi/8)].

    python tools/atan_coefficients.py
"""

import mpmath as mp

DEGREE = 10


def main() -> None:
    mp.mp.dps = 60
    tan_pi_8 = mp.sqrt(2) - 1
    z_max = (tan_pi_8 * (1 + mp.mpf(2) ** -40)) ** 2

    def target(z):
        if z == 0:
            return mp.mpf(-1) / 3
        s = mp.sqrt(z)
        return (mp.atan(s) / s - 1) / z

    n = DEGREE + 1
    nodes = [z_max / 2 * (1 + mp.cos(mp.pi * (2 * k + 1) / (2 * n))) for k in range(n)]
    vandermonde = mp.matrix([[x**j for j in range(n)] for x in nodes])
    coefficients = [float(c) for c in mp.lu_solve(vandermonde, mp.matrix([target(x) for x in nodes]))]

    worst = mp.mpf(0)
    for i in range(3000):
        t = mp.mpf(float(tan_pi_8) * (i + 0.5) / 3000)
        z = t * t
        p = sum(mp.mpf(c) * z**j for j, c in enumerate(coefficients))
        exact = mp.atan(t)
        worst = max(worst, abs(t + t * z * p - exact) / exact * 2**52)
    print("coefficients, highest degree first:")
    for c in reversed(coefficients):
        print(f"  {c!r}")
    print(f"largest error of the polynomial: {float(worst):.3f} x 2^-52 relative to atan(t)")


if __name__ == "__main__":
    main()
