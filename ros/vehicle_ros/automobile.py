"""The ``automobile/...`` services and topics of Webots' ``ros_automobile`` controller
(``RosAutomobile.cpp``), over ``vehicle.Car``: every value is the car library's own.

Names are Webots' relative ones under the node's namespace: ``/automobile/...`` by default,
``/<name>/automobile/...`` with ``--name`` (ros/README.md, "Names"). Setters reply
``success = True`` as Webots' callbacks do; a value the library clamps or refuses prints the
library's warning (stderr and ``/rosout``) and the reply is still ``True``.
"""

from typing import Any, Callable, Dict, List, Tuple

import rospy
from webots_ros.msg import Float64Stamped
from webots_ros.srv import (
    automobile_get_dimensions,
    automobile_get_dimensionsResponse,
    get_bool,
    get_boolResponse,
    get_float,
    get_floatResponse,
    get_int,
    get_intResponse,
    set_bool,
    set_boolResponse,
    set_float,
    set_floatResponse,
    set_int,
    set_intResponse,
)

from vehicle_ros.calls import CarCalls

__all__ = ["Automobile", "SERVICES", "TOPICS"]

#: Setter services: relative name, service type, the ``vehicle.Car`` method it calls.
#: Units: rad (steering, positive right), km/h (cruising speed), 0..1 (throttle, brake), s
#: (indicator period). ``set_indicator`` takes 0 OFF, 1 RIGHT, 2 LEFT (``set_int`` as in
#: RosAutomobile.cpp; the driver-library page says ``set_bool``); ``set_wipers_mode`` is
#: Webots' alias of ``set_wiper_mode``.
SETTERS: List[Tuple[str, Any, str]] = [
    ("set_steering_angle", set_float, "setSteeringAngle"),
    ("set_cruising_speed", set_float, "setCruisingSpeed"),
    ("set_throttle", set_float, "setThrottle"),
    ("set_brake_intensity", set_float, "setBrakeIntensity"),
    ("set_indicator_period", set_float, "setIndicatorPeriod"),
    ("set_gear", set_int, "setGear"),
    ("set_indicator", set_int, "setIndicator"),
    ("set_wiper_mode", set_int, "setWiperMode"),
    ("set_wipers_mode", set_int, "setWiperMode"),
    ("set_hazard_flashers", set_bool, "setHazardFlashers"),
    ("set_dipped_beam", set_bool, "setDippedBeams"),
    ("set_antifog_light", set_bool, "setAntifogLights"),
    ("enable_limited_slip_differential", set_bool, "enableLimitedSlipDifferential"),
    ("enable_indicator_auto_disabling", set_bool, "enableIndicatorAutoDisabling"),
]

#: Getter services: relative name, service type, the ``vehicle.Car`` method. ``ask`` is
#: ignored, as in Webots. Control mode: 0 SPEED, 1 TORQUE; types and engine types are the
#: ``Car`` constants.
GETTERS: List[Tuple[str, Any, str]] = [
    ("get_cruising_speed", get_float, "getTargetCruisingSpeed"),
    ("get_indicator_period", get_float, "getIndicatorPeriod"),
    ("get_gear", get_int, "getGear"),
    ("get_gear_number", get_int, "getGearNumber"),
    ("get_indicator", get_int, "getIndicator"),
    ("get_control_mode", get_int, "getControlMode"),
    ("get_wiper_mode", get_int, "getWiperMode"),
    ("get_wipers_mode", get_int, "getWiperMode"),
    ("get_type", get_int, "getType"),
    ("get_engine_type", get_int, "getEngineType"),
    ("get_hazard_flashers", get_bool, "getHazardFlashers"),
    ("get_dipped_beam", get_bool, "getDippedBeams"),
    ("get_antifog_light", get_bool, "getAntifogLights"),
    ("get_backwards_light", get_bool, "getBackwardsLights"),
    ("get_brake_light", get_bool, "getBrakeLights"),
]

_RESPONSES = {
    set_float: set_floatResponse,
    set_int: set_intResponse,
    set_bool: set_boolResponse,
    get_float: get_floatResponse,
    get_int: get_intResponse,
    get_bool: get_boolResponse,
}

_WHEELS = ("front_right", "front_left", "rear_right", "rear_left")  # Car.WHEEL_* order

#: Topics (``webots_ros/Float64Stamped``): relative name and how to read it from the car.
#: km/h (current speed), rad (steering, encoders), rad/s (wheel speeds), rpm, 0..1.
TOPICS: List[Tuple[str, Callable[[Any], float]]] = [
    ("brake_intensity", lambda car: car.getBrakeIntensity()),
    ("current_speed", lambda car: car.getCurrentSpeed()),
    ("rpm", lambda car: car.getRpm()),
    ("steering_angle", lambda car: car.getSteeringAngle()),
    ("right_steering_angle", lambda car: car.getRightSteeringAngle()),
    ("left_steering_angle", lambda car: car.getLeftSteeringAngle()),
    ("throttle", lambda car: car.getThrottle()),
]
for _index, _wheel in enumerate(_WHEELS):
    TOPICS.append((f"{_wheel}_wheel_encoder", lambda car, i=_index: car.getWheelEncoder(i)))
for _index, _wheel in enumerate(_WHEELS):
    TOPICS.append((f"{_wheel}_wheel_speed", lambda car, i=_index: car.getWheelSpeed(i)))

#: Every service's relative name (without the ``automobile/`` prefix).
SERVICES: List[str] = [n for n, _, _ in SETTERS] + [n for n, _, _ in GETTERS] + ["get_dimensions"]

_TORQUE = 1  # Driver.TORQUE: ``rpm`` is published only in this control mode, as in Webots


class Automobile:
    """Advertises the automobile services and topics of one car and publishes the topics."""

    def __init__(self, car: Any, calls: CarCalls, namespace: str, frame_id: str) -> None:
        self._car = car
        self._prefix = f"{namespace}automobile/"
        self._calls = calls
        self._frame_id = frame_id
        self._services: List[rospy.Service] = []
        for name, kind, method in SETTERS:
            self._advertise(name, kind, self._setter(kind, getattr(car, method)))
        for name, kind, method in GETTERS:
            self._advertise(name, kind, self._getter(kind, getattr(car, method)))
        self._advertise("get_dimensions", automobile_get_dimensions, self._dimensions)
        self._publishers: Dict[str, rospy.Publisher] = {
            name: rospy.Publisher(f"{self._prefix}{name}", Float64Stamped, queue_size=1)
            for name, _ in TOPICS
        }

    def _advertise(self, name: str, kind: Any, handler: Callable[[Any], Any]) -> None:
        self._services.append(rospy.Service(f"{self._prefix}{name}", kind, handler))

    def _setter(self, kind: Any, method: Callable[[Any], None]) -> Callable[[Any], Any]:
        response = _RESPONSES[kind]

        def handle(request: Any) -> Any:
            self._calls.call(lambda: method(request.value))
            return response(True)

        return handle

    def _getter(self, kind: Any, method: Callable[[], Any]) -> Callable[[Any], Any]:
        response = _RESPONSES[kind]
        return lambda _request: response(self._calls.call(method))

    def _dimensions(self, _request: Any) -> automobile_get_dimensionsResponse:
        car = self._car
        values = self._calls.call(
            lambda: (
                car.getTrackFront(),
                car.getTrackRear(),
                car.getWheelbase(),
                car.getFrontWheelRadius(),
                car.getRearWheelRadius(),
            )
        )
        return automobile_get_dimensionsResponse(*values)

    def publish(self, stamp: rospy.Time) -> None:
        """Publishes every topic once (main thread, before the driver step: the state after
        the previous step, as RosAutomobile::step does)."""
        torque = self._car.getControlMode() == _TORQUE
        for name, read in TOPICS:
            if name == "rpm" and not torque:
                continue
            message = Float64Stamped()
            message.header.stamp = stamp
            message.header.frame_id = self._frame_id
            message.data = read(self._car)
            self._publishers[name].publish(message)

    def shutdown(self) -> None:
        """Withdraws the services (the master forgets them)."""
        for service in self._services:
            service.shutdown()
