"""What one gymnasium ``step()`` from Python costs beyond the same step in Rust (issue #33).

LaneKeep-v0 (a BmwX5, cast mounting, RoadSensor, no camera; 4 basic time steps of 10 ms per
action), straight-ahead actions. In the same process, each block of ``step()`` calls is
paired with a block of as many steps run from Rust on the same environment, just before or
just after it (alternately): ``bench_steps``, one Python call per block, runs
``sim::vec_env::TaskEnv::step`` alone for the single environment and
``sim::vec_env::VecEnv::step`` on a batch of one for the vector environment. Adjacent blocks
see nearly the same load from the rest of the machine, so the statistic is the median over
the pairs of (Python block - Rust block) per step, on two clocks: the wall time, and the
process's CPU time (``time.process_time``), which leaves out the time other processes of a
loaded machine take the core. For:

* ``LaneKeepEnv.step()``, the single environment, unwrapped;
* the same environment as ``gymnasium.make`` returns it (its ``OrderEnforcing`` and
  ``PassiveEnvChecker`` wrappers);
* ``VectorEnv(num_envs=1).step()``, the vector environment on one copy;
* ``LaneKeepEnv(copy=False).step()``, which returns the arrays the core writes into;

then the same single-environment pairs once the world's 40 s are over (a step then runs no
physics, only the observation and reward: a fraction of a microsecond of Rust, so the
difference is measured without the noise of a 70 µs step); what each part of the Python
``step()`` costs alone; and the vector environment's throughput at ``num_envs=16`` (car
steps per second).

    pip install ./python[gym] && python python/bench/gym_step.py
"""

import statistics
import time
import timeit

import gymnasium
import numpy as np

import webots_vehicle.gym as wvgym

BLOCK = 25  # steps per timed block (1 s of simulated time)
PAIRS = 1000
START = (20.0, -5.625, 0.0, 15.0, 0.0)  # x m, y m, yaw rad, speed m/s, lead speed m/s
OPTIONS = {"pose": START[:3], "speed": START[3]}
ZERO = (0.0, 0.0)


def pairs(step_block, rust_block, before=lambda: None):
    """(Python, Rust, difference) per step (us) of each pair, for the wall time and for
    the process's CPU time (the two clocks read around each block)."""
    wall, cpu = ([], [], []), ([], [], [])
    for i in range(PAIRS):
        before()  # outside the timing
        # Every other pair runs the Rust block first, so that neither half always follows
        # the other (the cache state and the simulated state one block on).
        blocks = (step_block, rust_block) if i % 2 == 0 else (rust_block, step_block)
        w0, c0 = time.perf_counter(), time.process_time()
        blocks[0]()
        w1, c1 = time.perf_counter(), time.process_time()
        blocks[1]()
        w2, c2 = time.perf_counter(), time.process_time()
        for out, (t0, t1, t2) in ((wall, (w0, w1, w2)), (cpu, (c0, c1, c2))):
            first, second = (t1 - t0) / BLOCK * 1e6, (t2 - t1) / BLOCK * 1e6
            py, rs = (first, second) if i % 2 == 0 else (second, first)
            out[0].append(py)
            out[1].append(rs)
            out[2].append(py - rs)
    return wall, cpu


def report(name, measured):
    print(f"{name}: {PAIRS} pairs of {BLOCK}-step blocks, per step (us), median")
    print(f"  {'clock':6s} {'Python':>9s} {'Rust':>9s} {'overhead':>9s}  (quartiles of the overhead)")
    for clock, (python_us, rust_us, difference_us) in zip(("wall", "CPU"), measured):
        q1, _, q3 = statistics.quantiles(difference_us, n=4)
        print(
            f"  {clock:6s} {statistics.median(python_us):9.2f} {statistics.median(rust_us):9.2f}"
            f" {statistics.median(difference_us):9.2f}  ({q1:.2f}, {q3:.2f})"
        )


def timed(step, action):
    def block():
        for _ in range(BLOCK):
            step(action)

    return block


single = wvgym.LaneKeepEnv()
single.reset(options=OPTIONS)
action = np.zeros(2, dtype=np.float32)


def on_road_before_the_end(env):
    # The world ends at 40 s, and the curve takes a straight car off the road (the lane
    # entry's on-road flag, the observation's last value, is then 0).
    return env.sim.time < 30.0 and env._buffer[-1] > 0.5


def restart_single():
    if not on_road_before_the_end(single):
        single.reset(options=OPTIONS)


rust_single = lambda: single._core.bench_steps(BLOCK, ZERO)  # noqa: E731
report(
    "LaneKeepEnv.step()",
    pairs(timed(single.step, action), rust_single, restart_single),
)

made = gymnasium.make("WebotsVehicle/LaneKeep-v0")
made.reset(options=OPTIONS)
inner = made.unwrapped


def restart_made():
    if not on_road_before_the_end(inner):
        made.reset(options=OPTIONS)


report(
    "gymnasium.make('WebotsVehicle/LaneKeep-v0').step() (wrappers)",
    pairs(timed(made.step, action), lambda: inner._core.bench_steps(BLOCK, ZERO), restart_made),
)

vec = wvgym.VectorEnv("LaneKeep", num_envs=1)
vec.reset(seed=0)
report(
    "VectorEnv(num_envs=1).step()",
    pairs(timed(vec.step, np.zeros((1, 2))), lambda: vec._core.bench_steps(BLOCK, START)),
)

single_views = wvgym.LaneKeepEnv(copy=False)
single_views.reset(options=OPTIONS)


def restart_views():
    if not on_road_before_the_end(single_views):
        single_views.reset(options=OPTIONS)


report(
    "LaneKeepEnv(copy=False).step()",
    pairs(
        timed(single_views.step, action),
        lambda: single_views._core.bench_steps(BLOCK, ZERO),
        restart_views,
    ),
)

# The world's duration over: steps run no physics (see the module docs).
over = wvgym.LaneKeepEnv()
over.reset(options=OPTIONS)
while not over.step(action)[3]:
    pass
report(
    "LaneKeepEnv.step() after the world's end (no physics)",
    pairs(timed(over.step, action), lambda: over._core.bench_steps(BLOCK, ZERO)),
)

# What each part of step() costs alone (on the finished environment: no physics), CPU time,
# best of 5 repeats of 200,000 calls.
core = over._core
views = wvgym.LaneKeepEnv(copy=False)
views.reset(options=OPTIONS)
while not views.step(action)[3]:
    pass
action64 = np.zeros(2)
parts = [
    ("_native.GymEnv.step(float32 array)", lambda: core.step(action)),
    ("_native.GymEnv.step(float64 array)", lambda: core.step(action64)),
    ("_native.GymEnv.step([0.0, 0.0])", lambda: core.step([0.0, 0.0])),
    ("_observation() (the observation dict)", over._observation),
    ("a method call (env.touching)", lambda: over.touching),
    ("info dict {'time': t}", lambda: {"time": 1.0}),
    ("LaneKeepEnv.step(float32 array)", lambda: over.step(action)),
    ("LaneKeepEnv(copy=False).step(float32 array)", lambda: views.step(action)),
]


def cpu_us(fn, number):
    return min(timeit.Timer(fn, timer=time.process_time).repeat(5, number)) / number * 1e6


print("Parts, after the world's end (CPU time, best of 5 x 200,000 calls, per call):")
rust_us = cpu_us(lambda: core.bench_steps(1000, ZERO), 200) / 1000
print(f"  {'Rust TaskEnv::step alone (bench_steps)':42s} {rust_us:7.3f} us")
for name, fn in parts:
    print(f"  {name:42s} {cpu_us(fn, 200_000):7.3f} us")

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
