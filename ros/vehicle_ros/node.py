"""``vehicle-ros``: a world's cars as Webots' ``ros_automobile`` controller exposes each.

The node loads a world through the project's ``vehicle.Car`` (the C API in this process), one
controller per car it serves (``webots_vehicle.controllers``, the project's extension), then
loops as Webots' ROS controller does: ``/clock`` (simulated time) → each car's enabled
sensors' topics and ``automobile/...`` topics → the service requests received since → one
world step (``basicTimeStep``; every served car's driver runs once). It stops when the
world's ``duration`` has elapsed, on Ctrl-C, or when the master goes away. One car keeps
Webots' names of one controller; several are each under their own name (ros/README.md,
"Names").
"""

import argparse
import os
import re
import socket
import sys
import time
from typing import Any, List, Optional, Tuple

import rosgraph
import rospy
from rosgraph_msgs.msg import Clock
from std_msgs.msg import String
from webots_ros.srv import (
    get_float,
    get_floatResponse,
    robot_get_device_list,
    robot_get_device_listResponse,
)

from vehicle_ros.automobile import Automobile
from vehicle_ros.calls import CarCalls, MainThreadCalls
from vehicle_ros.sensors import SensorInterface, ros_name

__all__ = ["choose_cars", "main", "sim_stamp", "unique_name"]

#: Seconds (wall) between two checks that the master is still there.
MASTER_CHECK_PERIOD = 1.0


def unique_name(robot_name: str, pid: int, host: str) -> str:
    """Webots' node name without ``--name``: ``<robot>_<pid>_<host>`` with ``-``, ``.``,
    space, ``(`` and ``)`` made ``_``. Webots puts its own process id there (one simulation
    per Webots process); here the simulation is this process, so its id."""
    return re.sub(r"[-. ()]", "_", f"{robot_name}_{pid}_{host}")


def sim_stamp(t: float) -> rospy.Time:
    """Simulated time ``t`` (s) as Webots' ROS controller stamps ``/clock``: whole seconds,
    then milliseconds."""
    secs = int(t)
    return rospy.Time(secs, int(round(1000.0 * (t - secs))) * 1_000_000)


def choose_cars(cars: List[Tuple[str, bool]], spec: Optional[str]) -> List[str]:
    """The names of the cars to serve, in the world's order, of ``cars`` (the world's
    ``(name, programmed)`` pairs) by ``--cars``: ``None`` serves every car without a
    programme (the only car of a one-car world, programme or not, as a Webots controller
    drives it), ``all`` every car, ``A,B`` those named. Raises ``ValueError`` for a selection
    that names no car, a name the world lacks or twice, or a world whose every car runs a
    programme (nothing to serve unless ``--cars`` says so). A world without cars gives none."""
    names = [name for name, _ in cars]
    if not names:  # a DifferentialWheels world: the caller reports that it has no car
        return []
    if spec is None:
        if len(cars) == 1:
            return names
        free = [name for name, programmed in cars if not programmed]
        if not free:
            raise ValueError(
                f"every car of the world runs its programme ({', '.join(names)}): "
                "choose the cars to serve with --cars all or --cars NAME,..."
            )
        return free
    if spec == "all":
        return names
    wanted = [name.strip() for name in spec.split(",")]
    for name in wanted:
        if name not in names:
            raise ValueError(
                f"--cars names {name!r}, which is no car of the world (its cars: {', '.join(names)})"
            )
        if wanted.count(name) > 1:
            raise ValueError(f"--cars names {name!r} twice")
    return [name for name in names if name in wanted]


def _arguments(argv: List[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        prog="vehicle-ros",
        description="Runs a world and exposes its cars through Webots' ROS 1 automobile interface.",
    )
    parser.add_argument(
        "--world",
        help="world file or shipped model name (as VEHICLE_WORLD; default: a BmwX5 on flat ground)",
    )
    parser.add_argument(
        "--name",
        help="node name and namespace: /NAME/automobile/... (default: <robot>_<pid>_<host>, names in /)",
    )
    parser.add_argument(
        "--cars",
        metavar="all|NAME,...",
        help="the cars to serve (default: every car without a programme; all: every car)",
    )
    parser.add_argument(
        "--auto-publish",
        action="store_true",
        help="enable every sensor at the basic time step (Webots' --auto-publish)",
    )
    parser.add_argument(
        "--realtime-factor",
        type=float,
        default=1.0,
        metavar="F",
        help="simulated seconds per wall second (default 1; 0: as fast as possible)",
    )
    parser.add_argument(
        "--ROS_MASTER_URI", dest="master_uri", help="the master (default: $ROS_MASTER_URI)"
    )
    args = parser.parse_args(argv)
    if not (args.realtime_factor >= 0.0 and args.realtime_factor < float("inf")):
        parser.error(f"--realtime-factor must be a finite number >= 0, not {args.realtime_factor}")
    if args.name is not None and not re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", args.name):
        parser.error(
            f"--name must be a ROS name (a letter, then letters, digits, _), not {args.name!r}"
        )
    return args


class _Robot:
    """The ``robot/...`` services Webots' controller has that a car's user needs."""

    def __init__(self, car: Any, calls: CarCalls, namespace: str) -> None:
        prefix = f"{namespace}robot/"
        devices = (car.getDeviceByIndex(i) for i in range(car.getNumberOfDevices()))
        names = [device.getName() for device in devices if device is not None]  # None: a hole
        self._services = [
            rospy.Service(
                f"{prefix}get_time",
                get_float,
                lambda _r: get_floatResponse(calls.call(car.getTime)),
            ),
            rospy.Service(
                f"{prefix}get_basic_time_step",
                get_float,
                lambda _r: get_floatResponse(calls.call(car.getBasicTimeStep)),
            ),
            rospy.Service(
                f"{prefix}get_device_list",
                robot_get_device_list,
                lambda _r: robot_get_device_listResponse(names),
            ),
        ]

    def shutdown(self) -> None:
        for service in self._services:
            service.shutdown()


class _Served:
    """One car the node serves: its controller's ``Car``, then its ROS interface."""

    def __init__(self, name: str) -> None:
        from vehicle import Car
        from webots_vehicle import controllers

        self.name = name
        self.select = lambda: controllers.select(name)
        self.select()
        self.car = Car()  # this car's controller: its devices, driver and car libraries

    def advertise(
        self, calls: MainThreadCalls, namespace: str, node: str, auto_publish: bool
    ) -> None:
        """Advertises the car's services and topics under ``namespace``; frame ids
        ``<node>/automobile`` as Webots'."""
        self.select()
        car_calls = CarCalls(calls, self.select)
        self.namespace = namespace
        self.automobile = Automobile(self.car, car_calls, namespace, frame_id=f"{node}/automobile")
        self.sensors = SensorInterface(self.car, car_calls, namespace, auto_publish)
        self.robot = _Robot(self.car, car_calls, namespace)

    def publish(self, step: int, stamp: rospy.Time) -> None:
        """The car's sensor and automobile topics (main thread)."""
        self.select()
        self.sensors.publish(step, stamp)
        self.automobile.publish(stamp)

    def shutdown(self) -> None:
        self.automobile.shutdown()
        self.sensors.shutdown()
        self.robot.shutdown()


def _load(args: argparse.Namespace) -> Tuple[str, List[_Served]]:
    """The node's name and the cars it serves, each with its controller; raises
    ``ValueError`` or ``RuntimeError`` (``webots_vehicle.WorldError``, a robot that is no
    car) with what is wrong."""
    from webots_vehicle import controllers

    names = choose_cars(controllers.cars(), args.cars)
    if len(names) > 1 and args.name is not None:
        raise ValueError(
            f"--name names one car's node; the world's {len(names)} cars "
            f"({', '.join(names)}) are each served under their own name "
            "(__ns:=/NS puts them all under /NS/)"
        )
    if not names:  # a DifferentialWheels robot: the car library's own error
        from vehicle import Car

        Car()
    served = [_Served(name) for name in names]
    if len(served) > 1:
        return unique_name("vehicle_ros", os.getpid(), socket.gethostname()), served
    if args.name is not None:
        return args.name, served
    return unique_name(served[0].car.getName(), os.getpid(), socket.gethostname()), served


def run(args: argparse.Namespace) -> int:
    """Loads the world, serves it until it ends; the process's exit status."""
    if args.master_uri:
        os.environ["ROS_MASTER_URI"] = args.master_uri
    if not rosgraph.is_master_online():
        print(
            f"[FATAL] vehicle-ros: no ROS master at {rosgraph.get_master_uri()} (start roscore or rosmaster)",
            file=sys.stderr,
        )
        return 1
    if args.world is not None:
        os.environ["VEHICLE_WORLD"] = args.world
    try:
        name, served = _load(args)
    except (RuntimeError, ValueError) as error:  # WorldError, a robot that is no car, --cars
        print(f"vehicle-ros: {error}", file=sys.stderr)
        return 1
    rospy.init_node(name, anonymous=False)
    calls = MainThreadCalls(on_warning=rospy.logwarn)
    for car in served:
        # One car: Webots' names of its controller (root namespace, or /NAME/ with --name).
        # Several: each under its own name, as Webots' controllers each started with
        # --name=<car>.
        if len(served) > 1:
            namespace, node = f"{rospy.get_namespace()}{ros_name(car.name)}/", ros_name(car.name)
        else:
            namespace = rospy.get_namespace() + (f"{args.name}/" if args.name else "")
            node = name
        car.advertise(calls, namespace, node, args.auto_publish)
    rospy.set_param("/use_sim_time", True)
    model_name = rospy.Publisher("/model_name", String, queue_size=1, latch=True)
    model_name.publish(String(name))
    clock = rospy.Publisher("/clock", Clock, queue_size=1)
    for car in served:
        rospy.loginfo("vehicle-ros: %s serves %sautomobile/...", car.name, car.namespace)

    world = served[0]  # any controller steps the one world
    basic_step_s = world.car.getBasicTimeStep() / 1000.0
    wall_start = time.monotonic()
    next_master_check = wall_start + MASTER_CHECK_PERIOD
    step = 0
    reason = "interrupted"
    while not rospy.is_shutdown():
        stamp = sim_stamp(world.car.getTime())
        clock.publish(Clock(stamp))
        for car in served:
            car.publish(step, stamp)
        calls.run_pending()
        world.select()
        if world.car.step() == -1:
            reason = "the world's duration has elapsed"
            break
        step += 1
        now = time.monotonic()
        if args.realtime_factor > 0.0:
            due = wall_start + step * basic_step_s / args.realtime_factor
            if due > now:
                time.sleep(due - now)
        if now >= next_master_check:
            next_master_check = now + MASTER_CHECK_PERIOD
            if not rosgraph.is_master_online():
                reason = "the master went away"
                break
    rospy.loginfo("vehicle-ros: stopping at t = %.3f s: %s", world.car.getTime(), reason)
    calls.close()
    if reason != "the master went away":
        # Unregistering asks the master, which would only time out if it has gone.
        for car in served:
            car.shutdown()
    rospy.signal_shutdown(reason)
    return 0


def main(argv: Optional[List[str]] = None) -> int:
    """The ``vehicle-ros`` command (ROS remappings such as ``__ns:=`` are rospy's)."""
    arguments = rospy.myargv(sys.argv if argv is None else argv)[1:]
    return run(_arguments(arguments))


if __name__ == "__main__":
    sys.exit(main())
