"""``vehicle-ros``: a world's car as Webots' ``ros_automobile`` controller exposes it.

The node loads a world through the project's ``vehicle.Car`` (the C API in this process),
then loops as Webots' ROS controller does: ``/clock`` (simulated time) → the enabled sensors'
topics → the ``automobile/...`` topics → the service requests received since → one driver
step (``basicTimeStep``). It stops when the world's ``duration`` has elapsed, on Ctrl-C, or
when the master goes away. See ros/README.md.
"""

import argparse
import os
import re
import socket
import sys
import time
from typing import Any, List, Optional

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
from vehicle_ros.calls import MainThreadCalls
from vehicle_ros.sensors import SensorInterface

__all__ = ["main", "sim_stamp", "unique_name"]

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


def _arguments(argv: List[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        prog="vehicle-ros",
        description="Runs a world and exposes its car through Webots' ROS 1 automobile interface.",
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

    def __init__(self, car: Any, calls: MainThreadCalls, namespace: str) -> None:
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
    from vehicle import Car  # loads the world named by VEHICLE_WORLD

    try:
        car = Car()
    except RuntimeError as error:  # webots_vehicle.WorldError, or a robot that is no car
        print(f"vehicle-ros: {error}", file=sys.stderr)
        return 1
    name = args.name or unique_name(car.getName(), os.getpid(), socket.gethostname())
    rospy.init_node(name, anonymous=False)
    namespace = rospy.get_namespace() + (f"{args.name}/" if args.name else "")
    rospy.set_param("/use_sim_time", True)
    calls = MainThreadCalls(on_warning=rospy.logwarn)
    model_name = rospy.Publisher("/model_name", String, queue_size=1, latch=True)
    model_name.publish(String(name))
    clock = rospy.Publisher("/clock", Clock, queue_size=1)
    automobile = Automobile(car, calls, namespace, frame_id=f"{name}/automobile")
    sensors = SensorInterface(car, calls, namespace, args.auto_publish)
    robot = _Robot(car, calls, namespace)
    rospy.loginfo("vehicle-ros: %s serves %sautomobile/...", car.getName(), namespace)

    basic_step_s = car.getBasicTimeStep() / 1000.0
    wall_start = time.monotonic()
    next_master_check = wall_start + MASTER_CHECK_PERIOD
    step = 0
    reason = "interrupted"
    while not rospy.is_shutdown():
        stamp = sim_stamp(car.getTime())
        clock.publish(Clock(stamp))
        sensors.publish(step, stamp)
        automobile.publish(stamp)
        calls.run_pending()
        if car.step() == -1:
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
    rospy.loginfo("vehicle-ros: stopping at t = %.3f s: %s", car.getTime(), reason)
    calls.close()
    if reason != "the master went away":
        # Unregistering asks the master, which would only time out if it has gone.
        automobile.shutdown()
        sensors.shutdown()
        robot.shutdown()
    rospy.signal_shutdown(reason)
    return 0


def main(argv: Optional[List[str]] = None) -> int:
    """The ``vehicle-ros`` command (ROS remappings such as ``__ns:=`` are rospy's)."""
    arguments = rospy.myargv(sys.argv if argv is None else argv)[1:]
    return run(_arguments(arguments))


if __name__ == "__main__":
    sys.exit(main())
