#!/usr/bin/python3
"""Coefficients of util/sincoskern.h's reduced sin and cos (sinCosFast) and
vmath's reduced exp: near-minimax polynomials by Lawson's iteratively
reweighted least squares (Lawson 1961; Rice, "The approximation of
functions", 1964) on a dense Chebyshev grid, their error measured in long
double. Prints C++ hex constants and the measured maximum errors.

  sin r = r + r^3 P(r^2), cos r = 1 - r^2/2 + r^4 Q(r^2) on |r| <= pi/4
  (absolute error); e^r = 1 + r + r^2 R(r) on |r| <= ln2/2 (relative)."""
import numpy as np

L = np.longdouble


def lawson(basis, target, weight, x, iters=400):
    """coefficients c minimising max |weight (basis(x) c - target)|"""
    A = basis(x) * weight[:, None]
    b = target * weight
    w = np.ones(len(x)) / len(x)
    for _ in range(iters):
        sw = np.sqrt(w)
        c = np.linalg.lstsq(A * sw[:, None], b * sw, rcond=None)[0]
        e = np.abs(A @ c - b)
        w = w * e
        w /= w.sum()
    return c


def hexs(c):
    return ", ".join(float(v).hex() for v in c)


def grid(a, b, n=20001):
    t = np.cos(np.pi * (np.arange(n) + 0.5) / n)
    return 0.5 * (a + b) + 0.5 * (b - a) * t


def main():
    rmax = np.pi / 4 * (1 + 2**-40)  # the reduction's |r| plus rounding
    r = grid(0, rmax)
    for ns in (3, 4, 5):  # sin: r^3 .. r^(2 ns + 1)
        basis = lambda x, ns=ns: np.stack([x**(3 + 2 * i) for i in range(ns)], 1)
        c = lawson(basis, np.sin(r) - r, np.ones_like(r), r)
        rl = np.linspace(L(0), L(rmax), 200001)
        p = rl + sum(L(float(ci)) * rl**(3 + 2 * i) for i, ci in enumerate(c))
        print("sin to r^%d: %s\n  max abs err %.3g" % (2 * ns + 1, hexs(c),
                                                     float(np.max(np.abs(p - np.sin(rl))))))
    for nc in (3, 4):  # cos: r^4 .. r^(2 nc + 2)
        basis = lambda x, nc=nc: np.stack([x**(4 + 2 * i) for i in range(nc)], 1)
        c = lawson(basis, np.cos(r) - 1 + r * r / 2, np.ones_like(r), r)
        rl = np.linspace(L(0), L(rmax), 200001)
        p = 1 - rl * rl / 2 + sum(L(float(ci)) * rl**(4 + 2 * i) for i, ci in enumerate(c))
        print("cos to r^%d: %s\n  max abs err %.3g" % (2 * nc + 2, hexs(c),
                                                     float(np.max(np.abs(p - np.cos(rl))))))
    rmax = np.log(2) / 2 * (1 + 2**-20)
    r = grid(-rmax, rmax)
    for ne in (5, 6):  # exp: r^2 .. r^(ne + 1), relative error
        basis = lambda x, ne=ne: np.stack([x**(2 + i) for i in range(ne)], 1)
        c = lawson(basis, np.exp(r) - 1 - r, np.exp(-r), r)
        rl = np.linspace(L(-rmax), L(rmax), 200001)
        p = 1 + rl + sum(L(float(ci)) * rl**(2 + i) for i, ci in enumerate(c))
        print("exp to r^%d: %s\n  max rel err %.3g" % (ne + 1, hexs(c),
                                                      float(np.max(np.abs(p / np.exp(rl) - 1)))))


if __name__ == "__main__":
    main()
