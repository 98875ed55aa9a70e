"""The `controller` and `vehicle` modules: Webots' Python names (shared/spec python-api.md),
the C API's values for the same state (through ctypes on the staged libraries), the shipped
models' geometry, the indicator, and bad input."""

import ctypes
import math

import pytest

import controller
import vehicle
from controller import Robot, Supervisor
from vehicle import Car, Driver
from webots_vehicle import WorldError

from conftest import ROOT, WORLDS

# Webots R2023's Python names, from python-api.md.
DRIVER_CONSTANTS = {
    "INDICATOR_OFF": 0,
    "INDICATOR_RIGHT": 1,
    "INDICATOR_LEFT": 2,
    "SPEED": 0,
    "TORQUE": 1,
    "DOWN": 0,
    "SLOW": 1,
    "NORMAL": 2,
    "FAST": 3,
}
CAR_CONSTANTS = {
    "TRACTION": 0,
    "PROPULSION": 1,
    "FOUR_BY_FOUR": 2,
    "COMBUSTION_ENGINE": 0,
    "ELECTRIC_ENGINE": 1,
    "PARALLEL_HYBRID_ENGINE": 2,
    "POWER_SPLIT_HYBRID_ENGINE": 3,
    "WHEEL_FRONT_RIGHT": 0,
    "WHEEL_FRONT_LEFT": 1,
    "WHEEL_REAR_RIGHT": 2,
    "WHEEL_REAR_LEFT": 3,
}
ROBOT_METHODS = ["step", "getTime", "getBasicTimeStep", "getDevice", "getName"]

# (getter, property, C function, C result type): every Driver getter without argument.
DRIVER_GETTERS = [
    ("getSteeringAngle", "steering_angle", "wbu_driver_get_steering_angle", ctypes.c_double),
    ("getTargetCruisingSpeed", "target_cruising_speed", "wbu_driver_get_target_cruising_speed", ctypes.c_double),
    ("getCurrentSpeed", "current_speed", "wbu_driver_get_current_speed", ctypes.c_double),
    ("getThrottle", "throttle", "wbu_driver_get_throttle", ctypes.c_double),
    ("getBrakeIntensity", "brake_intensity", "wbu_driver_get_brake_intensity", ctypes.c_double),
    ("getGear", "gear", "wbu_driver_get_gear", ctypes.c_int),
    ("getGearNumber", "gear_number", "wbu_driver_get_gear_number", ctypes.c_int),
    ("getControlMode", "control_mode", "wbu_driver_get_control_mode", ctypes.c_int),
    ("getRpm", "rpm", "wbu_driver_get_rpm", ctypes.c_double),
    ("getIndicator", "indicator", "wbu_driver_get_indicator", ctypes.c_int),
    ("getHazardFlashers", "hazard_flashers", "wbu_driver_get_hazard_flashers", ctypes.c_bool),
    ("getDippedBeams", "dipped_beams", "wbu_driver_get_dipped_beams", ctypes.c_bool),
    ("getAntifogLights", "antifog_lights", "wbu_driver_get_antifog_lights", ctypes.c_bool),
    ("getWiperMode", "wiper_mode", "wbu_driver_get_wiper_mode", ctypes.c_int),
]
CAR_GETTERS = [
    ("getType", "type", "wbu_car_get_type", ctypes.c_int),
    ("getEngineType", "engine_type", "wbu_car_get_engine_type", ctypes.c_int),
    ("getIndicatorPeriod", "indicator_period", "wbu_car_get_indicator_period", ctypes.c_double),
    ("getBackwardsLights", "backwards_lights", "wbu_car_get_backwards_lights", ctypes.c_bool),
    ("getBrakeLights", "brake_lights", "wbu_car_get_brake_lights", ctypes.c_bool),
    ("getTrackFront", "track_front", "wbu_car_get_track_front", ctypes.c_double),
    ("getTrackRear", "track_rear", "wbu_car_get_track_rear", ctypes.c_double),
    ("getWheelbase", "wheelbase", "wbu_car_get_wheelbase", ctypes.c_double),
    ("getFrontWheelRadius", "front_wheel_radius", "wbu_car_get_front_wheel_radius", ctypes.c_double),
    ("getRearWheelRadius", "rear_wheel_radius", "wbu_car_get_rear_wheel_radius", ctypes.c_double),
    ("getLeftSteeringAngle", "left_steering_angle", "wbu_car_get_left_steering_angle", ctypes.c_double),
    ("getRightSteeringAngle", "right_steering_angle", "wbu_car_get_right_steering_angle", ctypes.c_double),
]
# (setter, property or None, C function, C argument type).
SETTERS = [
    ("setSteeringAngle", "steering_angle", "wbu_driver_set_steering_angle", ctypes.c_double),
    ("setCruisingSpeed", "target_cruising_speed", "wbu_driver_set_cruising_speed", ctypes.c_double),
    ("setThrottle", "throttle", "wbu_driver_set_throttle", ctypes.c_double),
    ("setBrakeIntensity", "brake_intensity", "wbu_driver_set_brake_intensity", ctypes.c_double),
    ("setGear", "gear", "wbu_driver_set_gear", ctypes.c_int),
    ("setIndicator", "indicator", "wbu_driver_set_indicator", ctypes.c_int),
    ("setHazardFlashers", "hazard_flashers", "wbu_driver_set_hazard_flashers", ctypes.c_bool),
    ("setDippedBeams", "dipped_beams", "wbu_driver_set_dipped_beams", ctypes.c_bool),
    ("setAntifogLights", "antifog_lights", "wbu_driver_set_antifog_lights", ctypes.c_bool),
    ("setWiperMode", "wiper_mode", "wbu_driver_set_wiper_mode", ctypes.c_int),
    ("setIndicatorPeriod", "indicator_period", "wbu_car_set_indicator_period", ctypes.c_double),
    ("setLeftSteeringAngle", "left_steering_angle", "wbu_car_set_left_steering_angle", ctypes.c_double),
    ("setRightSteeringAngle", "right_steering_angle", "wbu_car_set_right_steering_angle", ctypes.c_double),
    ("enableLimitedSlipDifferential", None, "wbu_car_enable_limited_slip_differential", ctypes.c_bool),
    ("enableIndicatorAutoDisabling", None, "wbu_car_enable_indicator_auto_disabling", ctypes.c_bool),
]
READ_ONLY = {"current_speed", "gear_number", "control_mode", "rpm", "type", "engine_type",
             "backwards_lights", "brake_lights", "track_front", "track_rear", "wheelbase",
             "front_wheel_radius", "rear_wheel_radius"}


def test_the_class_hierarchy_and_constants_are_webots():
    assert issubclass(Supervisor, Robot)
    assert issubclass(Driver, Supervisor)
    assert issubclass(Car, Driver)
    assert controller.Robot is Robot and vehicle.Driver is Driver
    for name, value in DRIVER_CONSTANTS.items():
        assert getattr(Driver, name) == value, name
    for name, value in {**DRIVER_CONSTANTS, **CAR_CONSTANTS}.items():
        assert getattr(Car, name) == value, name
    for name in ROBOT_METHODS:
        assert callable(getattr(Robot, name)), name
    for getter, prop, _, _ in DRIVER_GETTERS + CAR_GETTERS:
        assert callable(getattr(Car, getter)), getter
        descriptor = getattr(Car, prop)
        assert isinstance(descriptor, property), prop
        assert (descriptor.fset is None) == (prop in READ_ONLY), prop
    for setter, _, _, _ in SETTERS:
        assert callable(getattr(Car, setter)), setter
    for name in ["step", "isInitialisationPossible", "getWheelEncoder", "getWheelSpeed"]:
        assert callable(getattr(Car, name)), name
    assert isinstance(Driver.__dict__["isInitialisationPossible"], staticmethod)


class CApi:
    """The staged libcar.so and libdriver.so through ctypes, as Webots' binding loads them.
    They hold their own simulator state, apart from the package's."""

    def __init__(self, lib_dir):
        self.car = ctypes.CDLL(str(lib_dir / "libcar.so"))
        self.driver = ctypes.CDLL(str(lib_dir / "libdriver.so"))

    def function(self, name, restype=None, argtypes=()):
        lib = self.driver if name.startswith("wbu_driver") else self.car
        f = getattr(lib, name)
        f.restype = restype
        f.argtypes = list(argtypes)
        return f

    def get(self, name, restype, *args):
        return self.function(name, restype, [ctypes.c_int] * len(args))(*args)

    def set(self, name, argtype, value):
        self.function(name, None, [argtype])(value)


def python_state(car):
    """Every getter's value through the methods."""
    state = {}
    for getter, _, _, _ in DRIVER_GETTERS + CAR_GETTERS:
        state[getter] = getattr(car, getter)()
    for i in range(4):
        state[f"getWheelEncoder({i})"] = car.getWheelEncoder(i)
        state[f"getWheelSpeed({i})"] = car.getWheelSpeed(i)
    state["getTime"] = car.getTime()
    state["getBasicTimeStep"] = car.getBasicTimeStep()
    return state


def c_state(c):
    state = {}
    for getter, _, function, restype in DRIVER_GETTERS + CAR_GETTERS:
        state[getter] = c.get(function, restype)
    for i in range(4):
        state[f"getWheelEncoder({i})"] = c.get("wbu_car_get_wheel_encoder", ctypes.c_double, i)
        state[f"getWheelSpeed({i})"] = c.get("wbu_car_get_wheel_speed", ctypes.c_double, i)
    state["getTime"] = c.get("wb_robot_get_time", ctypes.c_double)
    state["getBasicTimeStep"] = c.get("wb_robot_get_basic_time_step", ctypes.c_double)
    return state


# The commands both APIs get, in phases separated by 150 steps: speed mode with lights and
# steering, torque mode with gears and per-wheel steering, then values Webots warns about.
PHASES = [
    [("setCruisingSpeed", 40.0), ("setSteeringAngle", 0.12), ("setDippedBeams", True),
     ("setIndicator", 2), ("setWiperMode", 1), ("setIndicatorPeriod", 0.5)],
    [("setThrottle", 0.6), ("setGear", 2), ("setBrakeIntensity", 0.1), ("setHazardFlashers", True),
     ("setAntifogLights", True), ("setLeftSteeringAngle", -0.05), ("setRightSteeringAngle", -0.04),
     ("enableLimitedSlipDifferential", False), ("enableIndicatorAutoDisabling", False)],
    [("setGear", -1), ("setThrottle", 0.3), ("setBrakeIntensity", 0.0)],
    [("setGear", 99), ("setThrottle", 7.0), ("setIndicator", 5), ("setWiperMode", 9),
     ("setSteeringAngle", float("nan")), ("setIndicatorPeriod", -1.0),
     ("setCruisingSpeed", 1e9), ("setBrakeIntensity", -3.0)],
]


def test_every_call_returns_the_c_api_s_value_for_the_same_state(webots, staged_capi, capfd):
    webots.setenv("VEHICLE_WORLD", "BmwX5")
    c = CApi(staged_capi)
    try:
        car = Car()
        c.function("wbu_driver_init")()
        assert python_state(car) == c_state(c)
        setters = {s[0]: s for s in SETTERS}
        warnings = []
        for phase in PHASES:
            for name, value in phase:
                capfd.readouterr()
                getattr(car, name)(value)
                py_err = capfd.readouterr().err
                _, _, function, argtype = setters[name]
                c.set(function, argtype, value)
                c_err = capfd.readouterr().err
                # The same warning, word for word, or none from both.
                assert py_err == c_err, name
                warnings.append(py_err)
            for _ in range(150):
                assert car.step() == c.function("wbu_driver_step", ctypes.c_int)() == 0
            capfd.readouterr()
            py = python_state(car)
            py_err = capfd.readouterr().err
            c_values = c_state(c)
            c_err = capfd.readouterr().err
            # The getters' own warnings (rpm and gear in speed mode) are the C API's too.
            assert py_err == c_err
            # Same code, same inputs: the simulations agree bit for bit.
            assert py == c_values
            for getter, prop, _, _ in DRIVER_GETTERS + CAR_GETTERS:
                assert getattr(car, prop) == py[getter], prop
        # The last phase's values are Webots' warning cases; the first three phases have none.
        assert warnings[-8:] == [
            "Warning: this car has only 6 gears.\n",
            "Warning: 'throttle' should be smaller or equal to 1, used 1 instead.\n",
            "Warning: wbu_driver_set_indicator() called with an invalid 'state' argument (5)\n",
            "Warning: wbu_driver_set_wiper_mode() called with an invalid 'mode' argument (9)\n",
            "Warning: wbu_driver_set_steering_angle() called with an invalid 'steering_angle' argument (NaN)\n",
            "Warning: wbu_car_set_indicator_period() called with an invalid 'period' argument (-1)\n",
            "",
            "Warning: 'intensity' should be bigger or equal to 0, used 0 instead.\n",
        ]
        assert not any(warnings[:-8])
        assert car.getDevice("right_steer") is not None and car.getDevice("cockpit") is None
        assert car.getName() == "vehicle"
    finally:
        c.function("wbu_driver_cleanup")()


def test_steering_acts_on_physics_only_steps_alike_in_c_python_and_simulation(
    webots, staged_capi
):
    # Webots' steering setters move the steering motors at once: a controller that then steps
    # with wb_robot_step (no driver step) steers. The rule lives in the engine, so the C API,
    # the Python controller and webots_vehicle.Simulation (drivers=False) agree bit for bit.
    webots.setenv("VEHICLE_WORLD", "BmwX5")
    c = CApi(staged_capi)
    try:
        driver = Driver()
        c.function("wbu_driver_init")()
        assert driver.step() == c.function("wbu_driver_step", ctypes.c_int)() == 0
        driver.setSteeringAngle(0.2)
        c.function("wbu_driver_set_steering_angle", None, [ctypes.c_double])(0.2)
        robot_step = c.function("wb_robot_step", ctypes.c_int, [ctypes.c_int])
        for _ in range(50):
            assert Robot.step(driver, 10) == robot_step(10) == 0
        steering = driver.getSteeringAngle()
        c_steering = c.function("wbu_driver_get_steering_angle", ctypes.c_double)()
        assert steering == c_steering
        # The mean of the Ackermann angles of 0.2 rad (0.2006 on the BmwX5), reached.
        assert abs(steering - 0.2006) < 0.002
    finally:
        c.function("wbu_driver_cleanup")()
    import webots_vehicle as wv

    # The Simulation's telemetry reads the steering as its driver does, at a driver step: one
    # more (driver) step reads the sensors after the same 51 steps.
    sim = wv.Simulation("BmwX5")
    sim.step(1)
    sim.car.set_steering_angle(0.2)
    sim.step(50, drivers=False)
    sim.step(1)
    assert sim.car.state["steering_rad"] == pytest.approx(steering, rel=0, abs=1e-12)


# The shipped models' geometry (m), drive and engine types and gear counts, from Webots'
# PROTOs (shared/spec webots-vehicle.md §5.1; the C-Zero with its rear tyre in both rear
# slots): wheelbase, front and rear track, front and rear tyre radius, type, engine type,
# len(gearRatio).
MODELS = {
    "BmwX5": (2.995, 1.628, 1.628, 0.374, 0.374, 0, 0, 6),
    "CitroenCZero": (2.55, 1.31, 1.27, 0.28475, 0.28675, 1, 1, 2),
    "ToyotaPrius": (2.8, 1.628, 1.628, 0.317, 0.317, 0, 3, 2),
    "LincolnMKZ": (2.94, 1.64, 1.64, 0.358, 0.358, 2, 0, 7),
    "RangeRoverSportSVR": (2.71, 1.64, 1.64, 0.358, 0.358, 2, 0, 9),
    "TeslaModel3": (2.94, 1.72, 1.72, 0.36, 0.36, 1, 1, 2),
}


@pytest.mark.parametrize("model", sorted(MODELS))
def test_car_getters_give_the_shipped_model_s_geometry(webots, model):
    webots.setenv("VEHICLE_WORLD", model)
    car = Car()
    got = (car.wheelbase, car.track_front, car.track_rear, car.front_wheel_radius,
           car.rear_wheel_radius, car.type, car.engine_type, car.gear_number)
    assert got == MODELS[model]


def test_set_indicator_works_and_refuses_what_webots_warns_about(webots, capfd):
    driver = Driver()
    assert driver.getIndicator() == Driver.INDICATOR_OFF
    driver.setIndicator(Driver.INDICATOR_LEFT)
    assert driver.getIndicator() == 2 and driver.indicator == Driver.INDICATOR_LEFT
    driver.indicator = Driver.INDICATOR_RIGHT
    assert driver.getIndicator() == 1
    capfd.readouterr()
    driver.setIndicator(3)
    assert capfd.readouterr().err == (
        "Warning: wbu_driver_set_indicator() called with an invalid 'state' argument (3)\n"
    )
    assert driver.getIndicator() == 1
    # The indicator blinks: the right indicator lights its LED within one period (0.34 s).
    for _ in range(50):
        driver.step()
    assert driver.getIndicator() == 1
    driver.setIndicator(Driver.INDICATOR_OFF)
    assert driver.indicator == 0


def test_nan_inf_and_huge_values_leave_every_getter_finite(webots, capfd):
    car = Car()
    car.setCruisingSpeed(30)
    for _ in range(20):
        car.step()
    bad_floats = [float("nan"), float("inf"), float("-inf"), 1e308, -1e308]
    bad_ints = [2**31, -(2**31) - 1, 10**30, -(10**30)]
    for setter, prop, _, argtype in SETTERS:
        values = bad_ints if argtype is ctypes.c_int else bad_floats
        for value in values:
            getattr(car, setter)(value)  # never raises: Webots accepts it with a warning
            if prop is not None:
                setattr(car, prop, value)
            for _ in range(3):
                assert car.step() == 0
            state = python_state(car)
            state.update({prop: getattr(car, prop) for _, prop, _, _ in DRIVER_GETTERS + CAR_GETTERS})
            for key, v in state.items():
                assert math.isfinite(v), (setter, value, key, v)
    err = capfd.readouterr().err
    assert "Warning: wbu_driver_set_steering_angle() called with an invalid 'steering_angle' argument (NaN)" in err
    assert "Warning: this car has only 6 gears." in err
    # A value that is no number at all is a TypeError, as in Webots' ctypes binding.
    with pytest.raises(TypeError):
        car.setGear(2.5)
    with pytest.raises(TypeError):
        car.setSteeringAngle("left")


def test_an_unknown_world_raises_with_the_world_file_message(webots):
    webots.setenv("VEHICLE_WORLD", "BmwX6")
    with pytest.raises(WorldError) as e:
        Driver()
    assert str(e.value).startswith("cannot load the world VEHICLE_WORLD=BmwX6: ")
    assert "BmwX5" in str(e.value)
    world = WORLDS / "misspelt_key.toml"
    webots.setenv("VEHICLE_WORLD", str(world))
    with pytest.raises(WorldError, match=rf"{world}:5:1: unknown key 'vehicle.wheelbse'"):
        Robot()


def test_a_differential_wheels_world_has_a_robot_but_no_driver(webots):
    webots.setenv("VEHICLE_WORLD", str(ROOT / "sim" / "worlds" / "e-puck.toml"))
    assert not Driver.isInitialisationPossible()
    robot = Robot()
    assert robot.getName() == "robot"
    assert robot.getDevice("left wheel") is not None
    assert robot.step() == 0 and robot.getTime() == pytest.approx(robot.getBasicTimeStep() / 1000)
    with pytest.raises(RuntimeError, match="Only nodes based on the 'Car' node"):
        Driver()
