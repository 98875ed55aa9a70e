"""What one `Driver.step()` from Python costs beyond the same step from Rust.

Runs the default world's BmwX5 (or VEHICLE_WORLD's car) cruising at 50 km/h and times, in the
same process, short blocks of `Driver.step()` calls from Python, each followed at once by a
block of `wbu_driver_step` called from Rust (`_native.bench_driver_steps`). Adjacent blocks see
the same car states and nearly the same load from the rest of the machine, so the statistic is
the median over the pairs of (Python block - Rust block) per step; the per-step medians of
each side are printed too.

    pip install ./python && python python/bench/driver_step.py
"""

import statistics
import time

from vehicle import Driver
from webots_vehicle import _native

BLOCK = 200  # steps per timed block (2 s of simulated time at 10 ms)
PAIRS = 500

driver = Driver()
driver.setCruisingSpeed(50)
for _ in range(500):  # up to speed first: the steps timed are steady cruising
    driver.step()

step = driver.step
python_us, rust_us, difference_us = [], [], []
for _ in range(PAIRS):
    start = time.perf_counter()
    for _ in range(BLOCK):
        step()
    py = (time.perf_counter() - start) / BLOCK * 1e6
    rs = _native.bench_driver_steps(BLOCK) / BLOCK * 1e6
    python_us.append(py)
    rust_us.append(rs)
    difference_us.append(py - rs)

py = statistics.median(python_us)
rs = statistics.median(rust_us)
diff = statistics.median(difference_us)
q1, _, q3 = statistics.quantiles(difference_us, n=4)
print(f"{PAIRS} pairs of {BLOCK}-step blocks, per step:")
print(f"  Driver.step() from Python  {py:.3f} us (median)")
print(f"  wbu_driver_step from Rust  {rs:.3f} us (median)")
print(f"  difference                 {diff:.3f} us (median of pairs; quartiles {q1:.3f}, {q3:.3f})")
print(f"  ratio                      {(rs + diff) / rs:.3f}")
