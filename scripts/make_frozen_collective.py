#!/usr/bin/env python3
"""Writes the load collective of the frozen-collective scene (data/scenes/frozen_collective.csv).

A quasi-static description of a passenger coach's leading wheelset on a mixed line, set by hand
rather than solved; the assumptions are listed in data/scenes/frozen_collective.toml. The
collective is reproducible: a fixed seed, plain Python (no third-party modules).

    scripts/make_frozen_collective.py > data/scenes/frozen_collective.csv
"""

import math
import random

SEED = 20221
WHEEL_LOAD_N = 55e3  # static wheel load: 11.2 t axle load
LATERAL_ARM_M = 0.75  # e0: half the lateral distance of the nominal contact points
CG_HEIGHT_M = 1.6  # car body centre of gravity above the rail
G = 9.81
SEMI_WHEELBASE_M = 1.25  # bogie wheelbase 2.5 m
R0_M = 0.46  # nominal rolling radius
CONICITY = 0.17  # equivalent conicity of new S1002/60E1 1:40 for the pure-rolling line
FLANGE_CLEARANCE_M = 6.0e-3  # lateral shift at which the flange root touches (about 6 mm)

# (name, curve radius [m], share of running distance, speed [m/s], cant [m], states)
SECTIONS = [
    ("tangent", 0.0, 0.55, 44.0, 0.0, 440),
    ("R3000", 3000.0, 0.12, 44.0, 0.060, 120),
    ("R1500", 1500.0, 0.10, 36.0, 0.100, 110),
    ("R1000", 1000.0, 0.09, 30.0, 0.110, 110),
    ("R700", 700.0, 0.08, 25.0, 0.120, 110),
    ("R500", 500.0, 0.06, 22.0, 0.130, 110),
]

HEADER = (
    "section,dy_m,yaw_rad,load_left_N,load_right_N,lateral_force_left_N,"
    "lateral_force_right_N,speed_m_s,curve_radius_m,lateral_velocity_m_s,weight"
)


def tangent_state(rng):
    """Kinematic oscillation (Klingel) of a bogie wheelset, constrained in yaw."""
    amplitude = rng.uniform(0.0, 3.5e-3)
    phase = rng.uniform(0.0, 2.0 * math.pi)
    wavelength = 2.0 * math.pi * math.sqrt(R0_M * LATERAL_ARM_M / CONICITY) * 2.0
    k = 2.0 * math.pi / wavelength
    speed = 44.0
    dy = amplitude * math.sin(phase)
    # Bogie frame constraint: half of the free wheelset's yaw, so lateral creepage remains.
    yaw = 0.5 * amplitude * k * math.cos(phase)
    lateral_velocity = amplitude * k * speed * math.cos(phase)
    dq = rng.gauss(0.0, 0.05) * WHEEL_LOAD_N  # track irregularities: 5 % dynamic load
    return dy, yaw, WHEEL_LOAD_N + dq, WHEEL_LOAD_N - dq, None, None, speed, 0.0, lateral_velocity


def curve_state(rng, radius, speed, cant):
    """Leading wheelset of a bogie in steady curving, with scatter from track irregularities."""
    # Cant deficiency loads the outer (left in a right-hand curve) wheel.
    lateral_acc = speed**2 / radius - G * cant / 1.5
    dq = WHEEL_LOAD_N * CG_HEIGHT_M * lateral_acc / (G * LATERAL_ARM_M) * 0.5
    dq += rng.gauss(0.0, 0.04) * WHEEL_LOAD_N
    # Pure-rolling shift, increased for an under-radial leading axle, limited by the flange.
    pure_rolling = LATERAL_ARM_M * R0_M / (CONICITY * radius)
    dy = min(1.6 * pure_rolling + rng.gauss(0.0, 0.8e-3), FLANGE_CLEARANCE_M + 1.5e-3)
    yaw = SEMI_WHEELBASE_M / radius * rng.uniform(0.6, 1.0)  # angle of attack towards the flange
    lateral_force = None
    if dy >= FLANGE_CLEARANCE_M:
        # Flange contact: the outer wheel's guiding force, Y/Q 0.3 ... 0.6 in tight curves.
        lateral_force = rng.uniform(0.3, 0.6) * (WHEEL_LOAD_N + dq)
    lateral_velocity = rng.gauss(0.0, 0.02)
    return (dy, yaw, WHEEL_LOAD_N + dq, WHEEL_LOAD_N - dq, lateral_force, None, speed, radius,
            lateral_velocity)


def mirrored(state):
    """The same state in a curve of the other hand: left and right swap."""
    dy, yaw, ql, qr, yl, yr, speed, radius, vy = state
    return -dy, -yaw, qr, ql, yr, yl, speed, -radius, -vy


def fmt(value):
    return "" if value is None else f"{value:.6g}"


def main():
    rng = random.Random(SEED)
    print(HEADER)
    for name, radius, share, speed, cant, count in SECTIONS:
        for i in range(count):
            if radius == 0.0:
                state = tangent_state(rng)
            else:
                state = curve_state(rng, radius, speed, cant)
                if i % 2 == 1:
                    state = mirrored(state)  # as many left-hand as right-hand curves
            print(",".join([name] + [fmt(v) for v in state] + [fmt(share / count)]))


if __name__ == "__main__":
    main()
