"""Webots' ``vehicle`` module: ``Driver`` and ``Car``, so that a Webots car controller runs
unchanged::

    from vehicle import Driver
    driver = Driver()
    driver.setSteeringAngle(0.1)      # rad, positive turns right
    driver.setCruisingSpeed(20)       # km/h
    while driver.step() != -1:
        if driver.getTime() > 4:      # s
            driver.setSteeringAngle(0)

The car is the one of the world named by ``VEHICLE_WORLD`` (see the ``controller`` module).
Every call is the C API's ``wbu_driver_*``/``wbu_car_*`` function with Webots' semantics:
values Webots accepts with a warning are clamped or refused with that warning on stderr (never
an exception), and getters never return NaN. ``Driver`` derives from
``controller.Supervisor``; ``Car`` from ``Driver``. Each method has a snake_case property
(``driver.steering_angle = 0.1``), as in Webots' Python API.

Units: rad (positive steers right), km/h (speeds), rpm, m, rad/s, s.
"""

from controller import Supervisor
from controller._c import _c_double, _c_int
from webots_vehicle import _native

__all__ = ["Car", "Driver"]


def _c_bool(value: object) -> int:
    """``value``'s truth as the C API's 0/1 byte (Webots: ``ctypes.c_bool``)."""
    return 1 if value else 0


class Driver(Supervisor):
    """The driver library (Webots: ``vehicle.Driver``, ``wbu_driver_*``).

    Creating it loads the world and initialises the car and driver libraries
    (``wbu_driver_init``). A world whose robot is not a car raises RuntimeError with Webots'
    message (Webots ends the controller).
    """

    INDICATOR_OFF = 0
    INDICATOR_RIGHT = 1
    INDICATOR_LEFT = 2
    SPEED = 0
    TORQUE = 1
    DOWN = 0
    SLOW = 1
    NORMAL = 2
    FAST = 3

    def __init__(self) -> None:
        super().__init__()
        if not _native.wbu_driver_initialization_is_possible():
            raise RuntimeError("Only nodes based on the 'Car' node can use the car library.")
        _native.wbu_driver_init()

    # Stepping.

    def step(self) -> int:  # type: ignore[override]
        """Runs the driver library (lights, wheel-speed and rpm estimates, engine torque,
        brakes) and advances the simulation by one ``basicTimeStep``. Returns 0, or -1 once
        the world's ``duration`` has elapsed."""
        return _native.wbu_driver_step()

    @staticmethod
    def isInitialisationPossible() -> bool:
        """True if the world's robot is a car (loads the world first)."""
        return bool(_native.wbu_driver_initialization_is_possible())

    # Steering and speed.

    def setSteeringAngle(self, steeringAngle: float) -> None:
        """Ackermann steering to ``steeringAngle`` rad (positive turns right), within
        ``minSteeringAngle``..``maxSteeringAngle``. NaN and infinities are refused with a
        warning."""
        _native.wbu_driver_set_steering_angle(_c_double(steeringAngle))

    def getSteeringAngle(self) -> float:
        """The steering angle (rad, positive right)."""
        return _native.wbu_driver_get_steering_angle()

    def setCruisingSpeed(self, speed: float) -> None:
        """Cruise control to ``speed`` km/h (negative: reverse); selects SPEED mode. Speeds
        beyond ``maxVelocity`` are clamped with Webots' warning."""
        _native.wbu_driver_set_cruising_speed(_c_double(speed))

    def getTargetCruisingSpeed(self) -> float:
        """The cruising speed asked for (km/h)."""
        return _native.wbu_driver_get_target_cruising_speed()

    def getCurrentSpeed(self) -> float:
        """The speed estimated from the driven wheels (km/h)."""
        return _native.wbu_driver_get_current_speed()

    def setThrottle(self, throttle: float) -> None:
        """Throttle (0 to 1; out-of-range values are clamped with a warning); selects TORQUE
        mode."""
        _native.wbu_driver_set_throttle(_c_double(throttle))

    def getThrottle(self) -> float:
        """The throttle (0 to 1)."""
        return _native.wbu_driver_get_throttle()

    def setBrakeIntensity(self, intensity: float) -> None:
        """Brake intensity (0 to 1; out-of-range values are clamped with a warning)."""
        _native.wbu_driver_set_brake_intensity(_c_double(intensity))

    def getBrakeIntensity(self) -> float:
        """The brake intensity (0 to 1)."""
        return _native.wbu_driver_get_brake_intensity()

    # Gearbox and engine.

    def setGear(self, gear: int) -> None:
        """Engages ``gear`` (-1 reverse, 0 neutral, 1.. forward), clamped to
        -1..``getGearNumber() - 1`` with Webots' warning."""
        _native.wbu_driver_set_gear(_c_int(gear))

    def getGear(self) -> int:
        """The engaged gear (-1 reverse, 0 neutral, 1.. forward)."""
        return _native.wbu_driver_get_gear()

    def getGearNumber(self) -> int:
        """The number of entries of ``gearRatio``, reverse included."""
        return _native.wbu_driver_get_gear_number()

    def getControlMode(self) -> int:
        """``SPEED`` (0), ``TORQUE`` (1), or -1 before either is selected."""
        return _native.wbu_driver_get_control_mode()

    def getRpm(self) -> float:
        """The engine speed (rpm)."""
        return _native.wbu_driver_get_rpm()

    # Lights and wipers.

    def setIndicator(self, state: int) -> None:
        """``INDICATOR_OFF`` (0), ``INDICATOR_RIGHT`` (1) or ``INDICATOR_LEFT`` (2); other
        values are refused with a warning. (Webots' own binding calls a misspelt C function
        here; this one works.)"""
        _native.wbu_driver_set_indicator(_c_int(state))

    def getIndicator(self) -> int:
        """The indicator state (0 off, 1 right, 2 left)."""
        return _native.wbu_driver_get_indicator()

    def setHazardFlashers(self, state: bool) -> None:
        """Hazard flashers on (true) or off."""
        _native.wbu_driver_set_hazard_flashers(_c_bool(state))

    def getHazardFlashers(self) -> bool:
        """True if the hazard flashers are on."""
        return bool(_native.wbu_driver_get_hazard_flashers())

    def setDippedBeams(self, state: bool) -> None:
        """Dipped beams on (true) or off."""
        _native.wbu_driver_set_dipped_beams(_c_bool(state))

    def getDippedBeams(self) -> bool:
        """True if the dipped beams are on."""
        return bool(_native.wbu_driver_get_dipped_beams())

    def setAntifogLights(self, state: bool) -> None:
        """Antifog lights on (true) or off."""
        _native.wbu_driver_set_antifog_lights(_c_bool(state))

    def getAntifogLights(self) -> bool:
        """True if the antifog lights are on."""
        return bool(_native.wbu_driver_get_antifog_lights())

    def setWiperMode(self, mode: int) -> None:
        """``DOWN`` (0), ``SLOW`` (1), ``NORMAL`` (2) or ``FAST`` (3); other values are
        refused with a warning; ignored by a car without wipers."""
        _native.wbu_driver_set_wiper_mode(_c_int(mode))

    def getWiperMode(self) -> int:
        """The wiper mode (0 DOWN to 3 FAST)."""
        return _native.wbu_driver_get_wiper_mode()

    # Properties (Webots' snake_case names).

    @property
    def steering_angle(self) -> float:
        """Steering angle (rad, positive right)."""
        return self.getSteeringAngle()

    @steering_angle.setter
    def steering_angle(self, value: float) -> None:
        self.setSteeringAngle(value)

    @property
    def target_cruising_speed(self) -> float:
        """Cruising speed asked for (km/h); setting it calls ``setCruisingSpeed``."""
        return self.getTargetCruisingSpeed()

    @target_cruising_speed.setter
    def target_cruising_speed(self, value: float) -> None:
        self.setCruisingSpeed(value)

    @property
    def current_speed(self) -> float:
        """Speed estimated from the driven wheels (km/h)."""
        return self.getCurrentSpeed()

    @property
    def throttle(self) -> float:
        """Throttle (0 to 1)."""
        return self.getThrottle()

    @throttle.setter
    def throttle(self, value: float) -> None:
        self.setThrottle(value)

    @property
    def brake_intensity(self) -> float:
        """Brake intensity (0 to 1)."""
        return self.getBrakeIntensity()

    @brake_intensity.setter
    def brake_intensity(self, value: float) -> None:
        self.setBrakeIntensity(value)

    @property
    def gear(self) -> int:
        """Engaged gear (-1 reverse, 0 neutral, 1.. forward)."""
        return self.getGear()

    @gear.setter
    def gear(self, value: int) -> None:
        self.setGear(value)

    @property
    def gear_number(self) -> int:
        """Entries of ``gearRatio``, reverse included."""
        return self.getGearNumber()

    @property
    def control_mode(self) -> int:
        """``SPEED`` (0), ``TORQUE`` (1) or -1."""
        return self.getControlMode()

    @property
    def rpm(self) -> float:
        """Engine speed (rpm)."""
        return self.getRpm()

    @property
    def indicator(self) -> int:
        """Indicator state (0 off, 1 right, 2 left)."""
        return self.getIndicator()

    @indicator.setter
    def indicator(self, value: int) -> None:
        self.setIndicator(value)

    @property
    def hazard_flashers(self) -> bool:
        """Hazard flashers."""
        return self.getHazardFlashers()

    @hazard_flashers.setter
    def hazard_flashers(self, value: bool) -> None:
        self.setHazardFlashers(value)

    @property
    def dipped_beams(self) -> bool:
        """Dipped beams."""
        return self.getDippedBeams()

    @dipped_beams.setter
    def dipped_beams(self, value: bool) -> None:
        self.setDippedBeams(value)

    @property
    def antifog_lights(self) -> bool:
        """Antifog lights."""
        return self.getAntifogLights()

    @antifog_lights.setter
    def antifog_lights(self, value: bool) -> None:
        self.setAntifogLights(value)

    @property
    def wiper_mode(self) -> int:
        """Wiper mode (0 DOWN to 3 FAST)."""
        return self.getWiperMode()

    @wiper_mode.setter
    def wiper_mode(self, value: int) -> None:
        self.setWiperMode(value)


class Car(Driver):
    """The car library on top of the driver library (Webots: ``vehicle.Car``,
    ``wbu_car_*``): geometry, wheels, per-wheel steering, lights."""

    TRACTION = 0
    PROPULSION = 1
    FOUR_BY_FOUR = 2
    COMBUSTION_ENGINE = 0
    ELECTRIC_ENGINE = 1
    PARALLEL_HYBRID_ENGINE = 2
    POWER_SPLIT_HYBRID_ENGINE = 3
    WHEEL_FRONT_RIGHT = 0
    WHEEL_FRONT_LEFT = 1
    WHEEL_REAR_RIGHT = 2
    WHEEL_REAR_LEFT = 3

    def getType(self) -> int:
        """Driven axle(s): ``TRACTION`` (front), ``PROPULSION`` (rear), ``FOUR_BY_FOUR``."""
        return _native.wbu_car_get_type()

    def getEngineType(self) -> int:
        """``COMBUSTION_ENGINE``, ``ELECTRIC_ENGINE``, ``PARALLEL_HYBRID_ENGINE`` or
        ``POWER_SPLIT_HYBRID_ENGINE``."""
        return _native.wbu_car_get_engine_type()

    def setIndicatorPeriod(self, period: float) -> None:
        """Duration of each on and each off phase of the indicators (s); NaN, infinities and
        periods <= 0 are refused with a warning."""
        _native.wbu_car_set_indicator_period(_c_double(period))

    def getIndicatorPeriod(self) -> float:
        """The indicator period (s)."""
        return _native.wbu_car_get_indicator_period()

    def getBackwardsLights(self) -> bool:
        """True while the reversing lights are lit."""
        return bool(_native.wbu_car_get_backwards_lights())

    def getBrakeLights(self) -> bool:
        """True while the brake lights are lit."""
        return bool(_native.wbu_car_get_brake_lights())

    def getTrackFront(self) -> float:
        """Distance between the front wheels (m)."""
        return _native.wbu_car_get_track_front()

    def getTrackRear(self) -> float:
        """Distance between the rear wheels (m)."""
        return _native.wbu_car_get_track_rear()

    def getWheelbase(self) -> float:
        """Distance between the axles (m)."""
        return _native.wbu_car_get_wheelbase()

    def getFrontWheelRadius(self) -> float:
        """Front tyre radius (m)."""
        return _native.wbu_car_get_front_wheel_radius()

    def getRearWheelRadius(self) -> float:
        """Rear tyre radius (m)."""
        return _native.wbu_car_get_rear_wheel_radius()

    def getWheelEncoder(self, wheel: int) -> float:
        """Rotation of wheel ``wheel`` (``WHEEL_FRONT_RIGHT`` .. ``WHEEL_REAR_LEFT``) in rad,
        continuous, positive rolling forward. Another index prints Webots' warning and gives
        0."""
        return _native.wbu_car_get_wheel_encoder(_c_int(wheel))

    def getWheelSpeed(self, wheel: int) -> float:
        """Rotation speed of wheel ``wheel`` (rad/s, positive rolling forward), measured by
        the last ``step()``."""
        return _native.wbu_car_get_wheel_speed(_c_int(wheel))

    def setLeftSteeringAngle(self, angle: float) -> None:
        """Steers the front left wheel to ``angle`` rad (positive right), without Ackermann
        geometry."""
        _native.wbu_car_set_left_steering_angle(_c_double(angle))

    def getLeftSteeringAngle(self) -> float:
        """The front left wheel's measured steering angle (rad)."""
        return _native.wbu_car_get_left_steering_angle()

    def setRightSteeringAngle(self, angle: float) -> None:
        """Steers the front right wheel to ``angle`` rad (positive right), without Ackermann
        geometry."""
        _native.wbu_car_set_right_steering_angle(_c_double(angle))

    def getRightSteeringAngle(self) -> float:
        """The front right wheel's measured steering angle (rad)."""
        return _native.wbu_car_get_right_steering_angle()

    def enableLimitedSlipDifferential(self, enable: bool) -> None:
        """Switches the limited-slip differential on (the default) or off."""
        _native.wbu_car_enable_limited_slip_differential(_c_bool(enable))

    def enableIndicatorAutoDisabling(self, enable: bool) -> None:
        """Switches the indicators' auto-cancelling on (the default) or off."""
        _native.wbu_car_enable_indicator_auto_disabling(_c_bool(enable))

    @property
    def type(self) -> int:
        """Driven axle(s) (see ``getType``)."""
        return self.getType()

    @property
    def engine_type(self) -> int:
        """Engine model (see ``getEngineType``)."""
        return self.getEngineType()

    @property
    def indicator_period(self) -> float:
        """Indicator period (s)."""
        return self.getIndicatorPeriod()

    @indicator_period.setter
    def indicator_period(self, value: float) -> None:
        self.setIndicatorPeriod(value)

    @property
    def backwards_lights(self) -> bool:
        """Reversing lights lit."""
        return self.getBackwardsLights()

    @property
    def brake_lights(self) -> bool:
        """Brake lights lit."""
        return self.getBrakeLights()

    @property
    def track_front(self) -> float:
        """Front track (m)."""
        return self.getTrackFront()

    @property
    def track_rear(self) -> float:
        """Rear track (m)."""
        return self.getTrackRear()

    @property
    def wheelbase(self) -> float:
        """Wheelbase (m)."""
        return self.getWheelbase()

    @property
    def front_wheel_radius(self) -> float:
        """Front tyre radius (m)."""
        return self.getFrontWheelRadius()

    @property
    def rear_wheel_radius(self) -> float:
        """Rear tyre radius (m)."""
        return self.getRearWheelRadius()

    @property
    def left_steering_angle(self) -> float:
        """Front left steering angle (rad)."""
        return self.getLeftSteeringAngle()

    @left_steering_angle.setter
    def left_steering_angle(self, value: float) -> None:
        self.setLeftSteeringAngle(value)

    @property
    def right_steering_angle(self) -> float:
        """Front right steering angle (rad)."""
        return self.getRightSteeringAngle()

    @right_steering_angle.setter
    def right_steering_angle(self, value: float) -> None:
        self.setRightSteeringAngle(value)
