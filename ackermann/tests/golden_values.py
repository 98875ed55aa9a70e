#!/usr/bin/env python3
"""Reference values of tests/golden.rs, computed independently of the crate.

Evaluates the Webots formulas literally (spec §2.4, §2.8, §2.9: atan(1/(cot δ ∓ k)), L/sin,
L/tan, Rr/(Rl+Rr), ...) at 40 significant digits with mpmath (`pip install mpmath`) for the
BMW X5 geometry: wheelbase 2.995 m, tracks 1.628 m, tyre radii 0.374 m, speed 20 km/h.
"""
from mpmath import mp, mpf, atan, tan, sin, cot

mp.dps = 40
L, Tf, Tr, rf, rr = mpf("2.995"), mpf("1.628"), mpf("1.628"), mpf("0.374"), mpf("0.374")
v = mpf(20) / mpf("3.6")  # m/s


def s(x):
    return mp.nstr(x, 17)


print("k = Tf/(2L) =", s(Tf / (2 * L)), "; 20 km/h / rf =", s(v / rf), "rad/s")
for d in ["0.1", "-0.1", "0.2", "-0.2", "0.5", "-0.5"]:
    d = mpf(d)
    right = atan(1 / (cot(d) - Tf / (2 * L)))
    left = atan(1 / (cot(d) + Tf / (2 * L)))
    R, Rf = L / tan(d), L / sin(d)
    wheels = [L / sin(right), L / sin(left), R - Tr / 2, R + Tr / 2]
    front = wheels[0] / (wheels[1] + wheels[0])
    rear = wheels[2] / (wheels[3] + wheels[2])
    # Webots multiplies this by rr/rf, a bug this project fixes (COMPATIBILITY.md).
    central = Rf / (Rf + R)
    print(f"delta {s(d)}")
    print("  angles R, L      ", s(right), s(left))
    print("  radii R, Rf      ", s(R), s(Rf))
    print("  wheel radii      ", *map(s, wheels))
    print("  ratios f, r, c   ", s(front), s(rear), s(central))
    print("  traction FR, FL  ", s(2 * v * front / rf), s(2 * v * (1 - front) / rf))
    print("  propulsion RR, RL", s(2 * v * rear / rr), s(2 * v * (1 - rear) / rr))
    print("  4x4 FR, FL, RR, RL", s(2 * v * front * 2 * central / rf),
          s(2 * v * (1 - front) * 2 * central / rf),
          s(2 * v * rear * 2 * (1 - central) / rr),
          s(2 * v * (1 - rear) * 2 * (1 - central) / rr))

# Central ratio with unequal tyres (rf = 0.35 m, rr = 0.4 m) at δ = 0.2 rad: the front axle's
# share of the path, Rf/(Rf + R), whatever the radii; Webots' q·Rf/(Rf + R) for comparison.
q = mpf("0.4") / mpf("0.35")
d = mpf("0.2")
share = (L / sin(d)) / (L / sin(d) + L / tan(d))
print("central at 0.2:", s(share), "; Webots with q = 0.4/0.35:", s(q * share))
