#!/usr/bin/env python3
"""Linear heave prediction for the irregular-sea Wigley scenarios
(wigley_*_jonswap_*.xml; docs/scenarios.md "Irregular seas").

The hull of models/wigley.xml: L = 4 m, B = 0.5 m, design draft T = 0.25 m,
half-breadth b(x, z) = B/2 (1 - (2x/L)^2) (1 - (z/T)^2) below the design
waterline, which floats e = 0.034 m above the sea; mass m = 176.2 kg.
Head seas along the hull (+x), deep water, eta = A cos(k x - w t).

Froude-Krylov heave force of the linear pressure p = rho g A e^{kz} cos(...)
on the wetted hull (Gauss's theorem over the wet volume V closed by the
waterplane W): F = rho g A [ int_W e^{ikx} dA - k int_V e^{kz} e^{ikx} dV ].
For a wall-sided hull of draft T this is rho g A e^{-kT} int_W e^{ikx} dA
(the box of seakeeping texts, e.g. Journee and Massie 2001, Offshore
Hydromechanics, ch. 6); the Wigley's sections narrow with depth, so the
exact volume integral is used: its depth factor is within 0.3% of the
wall-sided e^{-k T_m} at the mean draft T_m = V / A_W = 0.135 m for w up to
1.4 wp of the Tp 2.5 s sea (0.947, 0.917, 0.847 at w = 2, 2.51, 3.5 rad/s),
and well above e^{-k T} at the full wet draft 0.216 m (0.916, 0.870, 0.764).

Heave RAO: H(w) = F / (A (c - (m + a) w^2 + i b w)), c = rho g A_W.
mjbuoy has no radiation (added mass a, wave damping): a = 0 is its
equation; a = m (a typical low-frequency heave added mass of a slender
hull, Journee and Massie ch. 6) bounds what a radiation model would
change. b: linear damping (the scenarios keep the model's none; mjbuoy's
drag damps at resonance, which holds almost no wave energy here).

sigma_z^2 = int |H|^2 S dw (JONSWAP, DNV-RP-C205 (2010) eq. 3.5.5.4),
and with --sea FILE (mjbuoy-sim --print-sea output) also the prediction
from the realised components over a time window [t0, t1], where finite
records of a few dozen wave periods differ from the spectral value.

usage: heave_rao.py HS TP [--sea FILE --window T0 T1]
"""
import math
import sys

rho, g, L, B, T, e, m = 1000.0, 9.81, 4.0, 0.5, 0.25, 0.034, 176.2


def half(x, zh):  # zh from the design waterline, <= 0
    return B / 2 * (1 - (2 * x / L) ** 2) * (1 - (zh / T) ** 2)


NX, NZ = 400, 200
xs = [-L / 2 + L * (i + 0.5) / NX for i in range(NX)]
dx = L / NX
zlo, zhi = -T, -e  # wet part, design-waterline coordinates
dz = (zhi - zlo) / NZ
zs = [zlo + (j + 0.5) * dz for j in range(NZ)]
AW = sum(2 * half(x, -e) for x in xs) * dx
V = sum(2 * half(x, z) for x in xs for z in zs) * dx * dz


def fk(k):
    """Froude-Krylov heave force per unit amplitude [N/m] (real: the hull is symmetric fore-aft)"""
    top = sum(2 * half(x, -e) * math.cos(k * x) for x in xs) * dx
    decay = sum(2 * half(0.0, z) / B * math.exp(k * (z + e)) for z in zs) * dz  # per unit beam
    vol = sum(B * (1 - (2 * x / L) ** 2) * math.cos(k * x) for x in xs) * dx * decay
    return rho * g * (top - k * vol)


def jonswap(w, hs, tp, gam=3.3):
    wp = 2 * math.pi / tp
    s = 0.07 if w <= wp else 0.09
    pm = 5 / 16 * hs ** 2 * wp ** 4 * w ** -5 * math.exp(-1.25 * (wp / w) ** 4)
    return (1 - 0.287 * math.log(gam)) * pm * gam ** math.exp(-(w - wp) ** 2 / (2 * s * s * wp * wp))


def rao(w, a=0.0, b=0.0, cache={}):
    k = w * w / g
    if k not in cache:
        cache[k] = fk(k)
    c = rho * g * AW
    return cache[k] / complex(c - (m + a) * w * w, b * w)


def main():
    hs, tp = float(sys.argv[1]), float(sys.argv[2])
    wp = 2 * math.pi / tp
    c = rho * g * AW
    print("A_W %.4f m^2, V %.4f m^3 (m / rho %.4f), c %.0f N/m, wn %.3f rad/s" %
          (AW, V, m / rho, c, math.sqrt(c / m)))
    n = 700
    ws = [wp * (0.5 + 3.5 * (i + 0.5) / n) for i in range(n)]  # mjbuoy's default range
    dw = 3.5 * wp / n
    m0 = sum(jonswap(w, hs, tp) for w in ws) * dw
    print("sigma_eta %.5f m (Hs / 4 = %.5f)" % (math.sqrt(m0), hs / 4))
    for a, b in ((0, 0.05 * 2 * math.sqrt(c * m)), (0, 0.5 * 2 * math.sqrt(c * m)),
                 (m, 0.05 * 2 * math.sqrt(c * (2 * m)))):
        v = sum(abs(rao(w, a, b)) ** 2 * jonswap(w, hs, tp) for w in ws) * dw
        print("a %.0f kg, b %.0f N s/m: sigma_z %.5f m (ratio to sigma_eta %.3f)" %
              (a, b, math.sqrt(v), math.sqrt(v / m0)))
    for f in (0.5, 1, 1.5, 2, 3):
        w = f * wp
        print("  w %.2f wp: |FK| / (c A) %.3f, |H| %.3f" % (f, abs(rao(w)) * abs(1 - m * w * w / c),
                                                          abs(rao(w))))
    if "--sea" in sys.argv:
        comps = [[float(v) for v in l.split()[1:]] for l in open(sys.argv[sys.argv.index("--sea") + 1])
                 if l.strip() and not l.startswith("#")]
        t0, t1 = map(float, sys.argv[sys.argv.index("--window") + 1:][:2])
        for a, zeta in ((0, 0.05), (0, 0.5), (m, 0.05)):
            nt = int((t1 - t0) / 0.01)
            zsum = esum = z2 = e2 = 0
            for i in range(nt + 1):
                t = t0 + (t1 - t0) * i / nt
                z = eta = 0
                for A, w, k, d, ph, q in comps:
                    h = rao(w, a, zeta * 2 * math.sqrt(c * (m + a)))
                    th = -w * t + math.radians(ph)  # at x = 0
                    z += A * (h.real * math.cos(th) - h.imag * math.sin(th))
                    eta += A * math.cos(th)
                zsum += z; z2 += z * z; esum += eta; e2 += eta * eta
            N = nt + 1
            print("realised sea over [%g, %g] s, a %.0f kg, damping %.2f critical: sigma_z %.5f m, "
                  "sigma_eta(x=0) %.5f m" % (t0, t1, a, zeta, math.sqrt(z2 / N - (zsum / N) ** 2), math.sqrt(e2 / N - (esum / N) ** 2)))


if __name__ == "__main__":
    main()
