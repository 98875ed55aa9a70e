"""What one `Driver.step()` from Python costs beyond the same step from Rust.

Runs the default world's BmwX5 (or VEHICLE_WORLD's car) at 50 km/h and times, in the same
process and interleaved so that both see the same car states, blocks of `Driver.step()` calls
from Python and blocks of `wbu_driver_step` called from Rust (`_native.bench_driver_steps`).
Prints, for each, the fastest block (the least disturbed by other work on the machine, the
figure to compare) and the median block per step, and their differences and ratios.

    pip install ./python && python python/bench/driver_step.py
"""

import statistics
import time

from vehicle import Driver
from webots_vehicle import _native

BLOCK = 2000  # steps per timed block: 20 s of simulated time at 10 ms
ROUNDS = 30

driver = Driver()
driver.setCruisingSpeed(50)
for _ in range(500):  # up to speed first: the steps timed are steady cruising
    driver.step()

python_per_step, rust_per_step = [], []
step = driver.step
for _ in range(ROUNDS):
    start = time.perf_counter()
    for _ in range(BLOCK):
        step()
    python_per_step.append((time.perf_counter() - start) / BLOCK)
    rust_per_step.append(_native.bench_driver_steps(BLOCK) / BLOCK)

for label, pick in (("fastest block", min), ("median block", statistics.median)):
    py = pick(python_per_step) * 1e6
    rs = pick(rust_per_step) * 1e6
    print(
        f"{label} ({ROUNDS} blocks of {BLOCK} steps): Driver.step() from Python {py:.3f} us, "
        f"wbu_driver_step from Rust {rs:.3f} us per step; difference {py - rs:.3f} us, "
        f"ratio {py / rs:.3f}"
    )
