"""What one gymnasium ``step()`` from Python costs beyond the same step in Rust (issue #33).

LaneKeep-v0 (a BmwX5, cast mounting, RoadSensor, no camera; 4 basic time steps of 10 ms per
action), straight-ahead actions. In the same process, short blocks of ``step()`` calls are
each followed at once by a block of the same number of steps run from Rust
(``VecSim.bench_steps``: ``sim::vec_env::VecEnv::step`` on a batch of one, what
``vec_env/lane_keep/1`` measures in ``cargo bench -p benches --bench vec_env``). Adjacent
blocks see nearly the same load from the rest of the machine, so the statistic is the median
over the pairs of (Python block - Rust block) per step, for:

* ``LaneKeepEnv.step()``, the single environment (Python observation and reward code over
  the ``Simulation`` API);
* ``VectorEnv(num_envs=1).step()``, the vector environment on one copy;

and the vector environment's throughput at ``num_envs=16`` (car steps per second).
Episodes that end are reset outside the timed blocks (single) or by the autoreset (vector).

    pip install ./python[gym] && python python/bench/gym_step.py
"""

import statistics
import time

import numpy as np

import webots_vehicle.gym as wvgym

BLOCK = 25  # steps per timed block (1 s of simulated time)
PAIRS = 200
START = (20.0, -5.625, 0.0, 15.0, 0.0)  # x m, y m, yaw rad, speed m/s, lead speed m/s


def pairs(step_block, rust):
    python_us, rust_us, difference_us = [], [], []
    for _ in range(PAIRS):
        py = step_block() / BLOCK * 1e6
        rs = rust.bench_steps(BLOCK, START) / BLOCK * 1e6
        python_us.append(py)
        rust_us.append(rs)
        difference_us.append(py - rs)
    return python_us, rust_us, difference_us


def report(name, python_us, rust_us, difference_us):
    q1, _, q3 = statistics.quantiles(difference_us, n=4)
    print(f"{name}: {PAIRS} pairs of {BLOCK}-step blocks, per step")
    print(f"  Python step()      {statistics.median(python_us):9.2f} us (median)")
    print(f"  Rust step          {statistics.median(rust_us):9.2f} us (median)")
    print(
        f"  overhead           {statistics.median(difference_us):9.2f} us"
        f" (median of pairs; quartiles {q1:.2f}, {q3:.2f})"
    )


rust = wvgym.VectorEnv("LaneKeep", num_envs=1)
rust.reset(seed=0)
rust = rust._core

single = wvgym.LaneKeepEnv()
single.reset(options={"pose": START[:3], "speed": START[3]})
action = np.zeros(2, dtype=np.float32)


def single_block():
    if single.sim.time > 30.0:  # before the world's 40 s end, outside the timing
        single.reset(options={"pose": START[:3], "speed": START[3]})
    step = single.step
    begin = time.perf_counter()
    for _ in range(BLOCK):
        step(action)
    return time.perf_counter() - begin


report("LaneKeepEnv.step()", *pairs(single_block, rust))

vec = wvgym.VectorEnv("LaneKeep", num_envs=1)
vec.reset(seed=0)
actions = np.zeros((1, 2))


def vector_block():
    step = vec.step
    begin = time.perf_counter()
    for _ in range(BLOCK):
        step(actions)
    return time.perf_counter() - begin


report("VectorEnv(num_envs=1).step()", *pairs(vector_block, rust))

n = 16
wide = wvgym.VectorEnv("LaneKeep", num_envs=n)
wide.reset(seed=0)
wide_actions = np.zeros((n, 2))
for _ in range(10):
    wide.step(wide_actions)
begin = time.perf_counter()
steps = 250
for _ in range(steps):
    wide.step(wide_actions)
elapsed = time.perf_counter() - begin
car_steps = n * steps * 4
print(f"VectorEnv(num_envs={n}).step(): {car_steps / elapsed:.0f} car steps/s (one thread)")
