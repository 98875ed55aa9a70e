"""Several controllers in one process (``webots_vehicle.controllers``, the project's
extension that ``vehicle-ros`` serves every car of a world with): each car's ``Car`` reads
its own car and devices, and a step advances the one world once."""

import pytest
from conftest import ROOT

#: Two free cars 10 m apart (alpha has a gyro before its GPS) and a programmed third.
WORLD = str(ROOT / "capi" / "tests" / "worlds" / "two_cars.toml")


def test_each_car_has_its_controller(webots, capfd):
    import controller
    from vehicle import Car
    from webots_vehicle import WorldError, controllers

    webots.setenv("VEHICLE_WORLD", WORLD)
    assert controllers.cars() == [("alpha", False), ("beta", False), ("gamma", True)]
    assert controllers.current() is None
    with pytest.raises(ValueError, match="no car named 'delta'.*alpha, beta, gamma"):
        controllers.select("delta")

    cars = {}
    for name, speed, steering in (("alpha", 20.0, 0.1), ("beta", 10.0, -0.05)):
        controllers.select(name)
        assert controllers.current() == name
        cars[name] = Car()
        cars[name].setCruisingSpeed(speed)  # km/h
        cars[name].setSteeringAngle(steering)  # rad, positive right
    # One Car per controller is no second robot of a controller.
    assert "only one Robot instance" not in capfd.readouterr().err
    controllers.select("alpha")
    gps = {"alpha": cars["alpha"].getDevice("gps")}
    assert cars["alpha"].getDevice("gyro") is not None
    controllers.select("beta")
    gps["beta"] = cars["beta"].getDevice("gps")
    assert cars["beta"].getDevice("gyro") is None
    # Beta's GPS is its first sensor, alpha's its second: tags are per controller.
    assert gps["beta"]._tag == gps["alpha"]._tag - 1
    gps["beta"].enable(10)
    controllers.select("alpha")
    gps["alpha"].enable(10)

    # 300 steps of any controller are 3 s of the one world.
    for _ in range(300):
        assert cars["alpha"].step() == 0
    assert cars["beta"].getTime() == pytest.approx(3.0, abs=1e-9)

    for name, speed in (("alpha", 20.0), ("beta", 10.0)):
        controllers.select(name)
        assert cars[name].getTargetCruisingSpeed() == speed
        # The crate README's BmwX5 reaches 20 km/h in 3 s; 1 km/h for the cruise control
        # still settling while it turns.
        assert cars[name].getCurrentSpeed() == pytest.approx(speed, abs=1.0)
        # The GPS reads its own car: speed in m/s.
        assert gps[name].getSpeed() == pytest.approx(speed / 3.6, abs=0.3)
    # Started 10 m apart, alpha turning right, beta left.
    controllers.select("alpha")
    y_alpha = gps["alpha"].getValues()[1]
    controllers.select("beta")
    y_beta = gps["beta"].getValues()[1]
    assert y_beta - y_alpha > 10.0

    # A robot created again for a controller that has one is Webots' error.
    controllers.select("alpha")
    controller.Robot()
    assert "only one Robot instance" in capfd.readouterr().err
    # Cleanup frees every controller; a world that cannot be read is a WorldError.
    from webots_vehicle import _native

    _native.wb_robot_cleanup()
    assert controllers.current() is None
    webots.setenv("VEHICLE_WORLD", str(ROOT / "no-such-world.toml"))
    with pytest.raises(WorldError, match="no-such-world.toml"):
        controllers.cars()
