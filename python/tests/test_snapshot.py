"""Simulation.snapshot() / restore(): the run restored and continued repeats the run never
interrupted bit for bit (telemetry compared with ==, NaN where a quantity does not exist
compared by position), cars added since are dropped, another simulation's snapshot is
refused."""

import numpy as np
import pytest

import webots_vehicle as wv


def _same(a: np.ndarray, b: np.ndarray) -> bool:
    return a.shape == b.shape and np.array_equal(a, b, equal_nan=True)


@pytest.mark.parametrize("mounting", ["cast", "joints"])
def test_restore_continues_bit_for_bit(mounting):
    sim = wv.Simulation(vehicle={"model": "BmwX5", "mounting": mounting})
    car = sim.car
    car.set_cruising_speed(30.0)
    car.set_steering_angle(-0.05)
    sim.step(30)
    snap = sim.snapshot()
    assert snap.time == pytest.approx(0.3, abs=1e-12)
    sim.step(50)
    straight = car.telemetry.to_numpy()
    for _ in range(2):
        sim.restore(snap)
        assert sim.time == snap.time
        assert len(car.telemetry.to_numpy()) == 31  # the t = 0 sample and 30 steps
        sim.step(50)
        assert _same(car.telemetry.to_numpy(), straight)


def test_restore_drops_cars_added_since():
    sim = wv.Simulation()
    snap = sim.snapshot()
    sim.add_car("ToyotaPrius", translation=[0, 5, 0.4])
    assert len(sim.cars) == 2
    sim.restore(snap)
    assert len(sim.cars) == 1
    sim.step(5)
    assert len(sim.car.telemetry.to_numpy()) == 6


def test_another_simulations_snapshot_is_refused():
    first, second = wv.Simulation(), wv.Simulation()
    with pytest.raises(wv.SimulationError, match="another simulation"):
        first.restore(second.snapshot())
