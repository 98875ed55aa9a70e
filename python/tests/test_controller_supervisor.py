"""controller.Supervisor: Webots' placing subset (getFromDef, Node.getField, Field get/set,
getVelocity/setVelocity, resetPhysics, simulationReset) on the controller's world."""

import math

import pytest

from controller import Field, Supervisor

WORLD = """basicTimeStep = 10
[vehicle]
model = "BmwX5"
name = "ego"
[[body]]
translation = [0, 20, 0.5]
size = [1, 1, 1]
mass = 100
"""


@pytest.fixture
def supervisor(webots, tmp_path):
    world = tmp_path / "supervised.toml"
    world.write_text(WORLD)
    webots.setenv("VEHICLE_WORLD", str(world))
    return Supervisor()


def test_get_from_def_finds_cars_and_bodies(supervisor):
    assert supervisor.getFromDef("ego").getTypeName() == "Car"
    assert supervisor.getFromDef("body[1]").getTypeName() == "Solid"
    assert supervisor.getFromDef("body[2]") is None
    assert supervisor.getFromDef("nobody") is None
    assert supervisor.getFromDef("ego").getField("mass") is None


def test_translation_rotation_and_velocity_of_a_car(supervisor):
    for _ in range(100):  # settled on its springs
        supervisor.step(10)
    ego = supervisor.getFromDef("ego")
    translation = ego.getField("translation")
    rotation = ego.getField("rotation")
    assert translation.getType() == Field.SF_VEC3F
    z = translation.getSFVec3f()[2]
    translation.setSFVec3f([40.0, -10.0, z])
    rotation.setSFRotation([0, 0, 1, math.pi / 2])
    assert translation.getSFVec3f() == pytest.approx([40.0, -10.0, z], abs=1e-5)
    assert rotation.getSFRotation() == pytest.approx([0, 0, 1, math.pi / 2], abs=1e-6)
    ego.setVelocity([0.0, 15.0, 0.0, 0.0, 0.0, 0.0])  # forward, the car facing +y
    assert ego.getVelocity() == pytest.approx([0, 15, 0, 0, 0, 0])
    supervisor.step(10)
    x, y, _ = ego.getPosition()
    # 10 ms at about 15 m/s along +y (the driver library is not stepped: the wheels roll
    # free).
    assert x == pytest.approx(40.0, abs=1e-3)
    assert y == pytest.approx(-10.0 + 0.15, abs=2e-3)
    ego.resetPhysics()
    assert ego.getVelocity() == pytest.approx([0.0] * 6)
    with pytest.raises(ValueError, match="translation.x"):
        translation.setSFVec3f([1e5, 0, 0])
    with pytest.raises(TypeError):
        translation.getSFRotation()


def test_simulation_reset(supervisor):
    box = supervisor.getFromDef("body[1]")
    start = box.getPosition()
    box.getField("translation").setSFVec3f([3, 3, 3])
    supervisor.step(100)
    assert supervisor.getTime() == pytest.approx(0.1)
    supervisor.simulationReset()
    assert supervisor.getTime() == 0.0
    assert box.getPosition() == pytest.approx(start)
