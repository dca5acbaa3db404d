"""Heave RAO of the buoy (models/buoy.xml) in regular waves, time domain
against the frequency-domain prediction from the panel solver's
coefficients (the ones mjbuoy-hydro prints: A33, B33, X3 of the body).

    PYTHONPATH=build/python python3 examples/python/heave_rao.py -o rao.png

Time domain: for each wave period T, a regular wave of amplitude a and
deep-water length g T^2 / (2 pi) (set_sea), the heave after the start-up
transient fitted with a sinusoid at omega: RAO = heave amplitude / a.
Frequency domain (linear seakeeping, docs/physics.md):
    RAO(w) = |X3(w)| / |C33 - w^2 (m + A33(w)) + i w (B33(w) + b)|
with C33 = rho g A_wp (the sphere's waterplane pi (2 R h - h^2) at draft
h = 0.363 m), b the scene's simple linear damping C_lin r_s (docs/physics.md
section 4.3: C_lin = 1058 N s/m times the wet fraction of the hull's area,
r_s = h / (2 R) for a sphere). The time domain also has what the linear
model leaves out (exact hydrostatics over the moving hull, quadratic drag,
the wave pressure over the instantaneous wet surface); the script prints
both and their ratio.
"""
import argparse
import math
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import mjbuoy  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
G, RHO, R, H = 9.81, 1000.0, 0.5, 0.363258
DAMP = 1058.0 * H / (2 * R)  # C_lin r_s [N s/m]


def measured_rao(sim, period, amp, cycles):
    omega = 2 * math.pi / period
    sim.reset()
    sim.set_sea(waves=[[amp, G * period**2 / (2 * math.pi), 0.0, 0.0, 0.0]])
    z0 = 0.5 - H  # the calm-water equilibrium of the centre (models/buoy.xml)
    sim.qpos[2] = z0
    n = round(period / sim.timestep / 20)  # 20 samples a period
    t, z = [], []
    while sim.time < cycles * period:
        sim.step(n)
        t.append(sim.time)
        z.append(sim.qpos[2] - z0)
    t, z = np.array(t), np.array(z)
    keep = t > cycles * period / 2  # after the transient
    basis = np.column_stack([np.cos(omega * t[keep]), np.sin(omega * t[keep]), np.ones(keep.sum())])
    c, *_ = np.linalg.lstsq(basis, z[keep], rcond=None)
    return math.hypot(c[0], c[1]) / amp


def predicted_rao(coef, mass, omega):
    w = coef["omega"]
    a33 = np.interp(omega, w, coef["A"][:, 2, 2])
    b33 = np.interp(omega, w, coef["B"][:, 2, 2])
    x3 = np.interp(omega, w, np.abs(coef["X"][:, 0, 2]))  # heading index 0
    c33 = RHO * G * math.pi * (2 * R * H - H * H)
    return x3 / np.abs(c33 - omega**2 * (mass + a33) + 1j * omega * (b33 + DAMP))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("-o", "--output", default="heave_rao.png")
    p.add_argument("--amplitude", type=float, default=0.02, help="wave amplitude [m]")
    p.add_argument("--cycles", type=int, default=12, help="wave periods simulated per point")
    args = p.parse_args()
    # the calm scene reserves no wave components: room for set_sea's one
    sim = mjbuoy.Sim(str(ROOT / "models" / "buoy.xml"), sea__capacity=1)
    coef = sim.radiation("buoy")
    mass = 157.080
    periods = np.array([1.0, 1.4, 1.7, 2.0, 2.4, 3.0, 4.0])
    meas = [measured_rao(sim, T, args.amplitude, args.cycles) for T in periods]
    omega = 2 * np.pi / periods
    pred = predicted_rao(coef, mass, omega)
    for T, m_, p_ in zip(periods, meas, pred):
        print(f"T {T:4.1f} s  RAO time domain {m_:.3f}  frequency domain {p_:.3f}  "
              f"ratio {m_ / p_:.2f}")
    wf = np.linspace(omega.min(), omega.max(), 200)
    plt.figure(figsize=(6, 4))
    plt.plot(wf, predicted_rao(coef, mass, wf), label="frequency domain (panel coefficients)")
    plt.plot(omega, meas, "o", label="mjbuoy time domain")
    plt.xlabel("wave frequency omega [rad/s]")
    plt.ylabel("heave RAO [m/m]")
    plt.title("Heave RAO of the 0.5 m buoy (models/buoy.xml)")
    plt.legend()
    plt.tight_layout()
    plt.savefig(args.output, dpi=100)
    print("wrote", args.output)


if __name__ == "__main__":
    main()
