"""Adaptive cruise control with a radar alone, as a Webots Python controller.

    VEHICLE_WORLD=sim/worlds/acc.toml python examples/acc/acc.py

The car cruises at SET_SPEED until its radar (named "radar") reports a target ahead; then it
follows the nearest target at the distance STANDSTILL + TIME_GAP * v (v its own speed, m/s):
the cruising speed it commands is the target's speed (its own plus the target's radial speed)
plus GAIN times the distance error, between 0 and SET_SPEED. Below CREEP it stops (0), and
once stopped it waits for a command above RESUME, so that the radar's noise (0.5 m, 0.12 m/s)
neither makes it crawl nor restart behind a stopped target. The gap error then decays as
exp(-GAIN t) behind a target at constant speed. Every 0.5 s it prints "acc: t v d" (s, m/s,
m; d = -1 without a target). The same controller as acc.c.
"""

import math

from vehicle import Driver

TIME_GAP = 1.5  # s
STANDSTILL = 7.0  # m: radar distance to the target's origin (its rear axle) at rest
SET_SPEED = 25.0  # m/s
GAIN = 0.4  # 1/s
CREEP = 0.5  # m/s
RESUME = 1.5  # m/s
RADAR_PERIOD = 50  # ms

driver = Driver()
radar = driver.getDevice("radar")
radar.enable(RADAR_PERIOD)
steps = 0
while driver.step() != -1:
    # The driver library's speed, from the driven wheels (NaN until they are measurable).
    v = driver.getCurrentSpeed() / 3.6
    if math.isnan(v):
        v = 0.0
    command, distance = SET_SPEED, -1.0
    for target in radar.getTargets():
        if distance < 0.0 or target.distance < distance:
            lead = v + target.speed
            distance = target.distance
            command = lead + GAIN * (distance - (STANDSTILL + TIME_GAP * v))
    command = min(command, SET_SPEED)
    if command < (RESUME if v < 0.1 else CREEP):
        command = 0.0
    driver.setCruisingSpeed(command * 3.6)
    steps += 1
    if steps % 50 == 0:
        print(f"acc: {driver.getTime():.2f} {v:.4f} {distance:.4f}", flush=True)
