"""Supervisor placement on webots_vehicle.Simulation: a car put at a pose is there, a car
given a speed rolls on at it, bodies move where put, refusals, reset to the world as loaded.
The physics of the move is tested in Rust (sim/tests/supervisor.rs); these tests check the
marshalling (units, axis-angle, errors)."""

import math

import numpy as np
import pytest

import webots_vehicle as wv

WORLD = {
    "vehicle": {"model": "BmwX5"},
    "body": [{"translation": [0, 20, 0.5], "size": [1, 1, 1], "mass": 100}],
}


def test_a_car_put_at_a_pose_reads_it_back():
    sim = wv.Simulation(**WORLD)
    sim.step(100)  # settled on its springs
    z = sim.car.placement.translation[2]
    sim.car.set_pose([50.0, 30.0, z], [0, 0, 2, 1.0])  # any axis length
    p = sim.car.placement
    assert p.translation == pytest.approx((50.0, 30.0, z), abs=1e-5)
    assert p.rotation == pytest.approx((0, 0, 1, 1.0), abs=1e-6)
    sim.step(1)
    # Within the settled springs' motion of a step (< 1 mm).
    assert sim.car.placement.translation == pytest.approx((50.0, 30.0, z), abs=1e-3)


def test_a_car_given_a_speed_rolls_on():
    sim = wv.Simulation(**WORLD)
    sim.step(100)
    sim.car.set_pose(sim.car.placement.translation, [0, 0, 1, math.pi / 2])  # facing +y
    sim.car.set_velocity([0.0, 20.0, 0.0])
    assert sim.car.placement.velocity == pytest.approx((0.0, 20.0, 0.0))
    sim.step(10)
    # The driver library holds the car in SPEED mode at 0 km/h: it brakes, but 0.1 s
    # cannot take more than μ·g·t ≈ 1 m/s of the 20.
    speed = sim.car.state["speed_kmh"] / 3.6
    assert 18.9 < speed <= 20.0


def test_bodies_and_refusals():
    sim = wv.Simulation(**WORLD)
    (box,) = sim.bodies
    box.set_pose([5, -5, 3])
    box.set_velocity([1, 0, 0])
    assert box.placement.translation == pytest.approx((5, -5, 3))
    assert box.placement.velocity == pytest.approx((1, 0, 0))
    with pytest.raises(ValueError, match="translation.x"):
        sim.car.set_pose([2e4, 0, 0.5])
    with pytest.raises(ValueError, match="rotation"):
        sim.car.set_pose([0, 0, 0.5], [0, 0, 0, 1])
    with pytest.raises(ValueError, match="velocity.x"):
        sim.car.set_velocity([float("nan"), 0, 0])
    with pytest.raises(ValueError, match="3 numbers"):
        sim.car.set_velocity([1, 0])


def test_reset_gives_the_world_as_loaded():
    sim = wv.Simulation(**WORLD)
    start = sim.car.placement
    sim.car.set_cruising_speed(30)
    sim.step(50)
    first = sim.car.telemetry.to_numpy()
    sim.reset()
    assert sim.time == 0.0
    assert sim.car.placement == start
    sim.car.set_cruising_speed(30)
    sim.step(50)
    # Bit for bit (NaN where a quantity does not exist, at the same places).
    assert np.array_equal(sim.car.telemetry.to_numpy(), first, equal_nan=True)
