#!/usr/bin/env python3
"""Derive the polynomial coefficients of problems/core/vector_math.cpp.

Usage: vector-math-coefficients.py   (needs mpmath: Debian's python3-mpmath)

Prints, as C++ hexadecimal literals from the highest degree down (the order of the Horner loops):
  exp: q(r) ~ (exp(r) - 1 - r) / r^2, degree 9, on |r| <= ln 2 / 2 (exp(r) = 1 + r + r^2 q(r));
  log: p(z) ~ (log((1 + s) / (1 - s)) - 2s) / s^3, z = s^2, degree 6, on s in [0, (sqrt 2 - 1) /
       (sqrt 2 + 1)] (log(1 + f) = 2s + s z p(z), s = f / (2 + f));
each a Chebyshev fit (mpmath.chebyfit, near-minimax) at 50 digits rounded to double, with its
error bound as it enters the result (times r^2, resp. s z). The intervals are widened by 2^-40 for
the rounding of the reduction. Also the split ln 2 = ln2_hi (32 significant bits) + ln2_lo.
"""
import mpmath as mp

mp.mp.dps = 50
ln2 = mp.log(2)
widen = 1 + mp.mpf(2) ** -40


def exp_q(r):
    if abs(r) < mp.mpf(10) ** -20:
        return mp.mpf(1) / 2 + r / 6
    return (mp.exp(r) - 1 - r) / r ** 2


def log_p(z):
    if z < mp.mpf(10) ** -30:
        return mp.mpf(2) / 3
    s = mp.sqrt(z)
    return (mp.log((1 + s) / (1 - s)) - 2 * s) / s ** 3


def show(name, f, interval, degree, weight):
    coefficients, error = mp.chebyfit(f, interval, degree + 1, error=True)
    print(f"{name}: degree {degree}, error in the result <= {mp.nstr(error * weight, 3)}")
    for c in coefficients:
        print("   ", float(c).hex())


r_max = ln2 / 2 * widen
s_max = (mp.sqrt(2) - 1) / (mp.sqrt(2) + 1)
z_max = s_max ** 2 * widen
show("exp q", exp_q, [-r_max, r_max], 9, r_max ** 2)
show("log p", log_p, [0, z_max], 6, s_max * z_max)
ln2_hi = mp.floor(ln2 * 2 ** 32) / 2 ** 32
print("ln2_hi", float(ln2_hi).hex(), "ln2_lo", float(ln2 - ln2_hi).hex(), "log2_e", float(1 / ln2).hex())
