"""Several controllers in one process, one per car of a world: the project's extension (no
Webots counterpart), with which one program serves every car of a world, as the ROS node
``vehicle-ros`` does.

In Webots each car runs its own controller process. Here the Webots modules (``controller``,
``vehicle``) act on the process's current controller: the one car a Webots controller drives
(the only car, or the one without a programme), unless :func:`select` picks another. Each
selected car gets a controller of its own (device tags, sensor buffers, driver and car
libraries; the car stops running its world-file programme), and a ``Robot``/``Car`` created
while it is selected is that car's. Every call goes to the controller selected at the time of
the call, so a program that serves several cars selects before it calls::

    from vehicle import Car
    from webots_vehicle import controllers

    cars = {}
    for name, _programmed in controllers.cars():
        controllers.select(name)
        cars[name] = Car()
    controllers.select("alpha"); cars["alpha"].setCruisingSpeed(30)   # km/h
    controllers.select("beta"); cars["beta"].setCruisingSpeed(10)
    cars["beta"].step()   # one world step: every car's driver runs once

A step of any controller (``Driver.step()``, ``Robot.step()``) advances the one world once.
"""

from typing import List, Optional, Tuple

from webots_vehicle import _native

__all__ = ["cars", "current", "select"]


def cars() -> List[Tuple[str, bool]]:
    """The world's cars in file order as ``(name, programmed)``: the loaded world's, or before
    any is loaded those of the world ``VEHICLE_WORLD`` names (read, not loaded). ``programmed``
    is True for a car with a ``[[vehicle.programme]]``. Empty for a DifferentialWheels world;
    a world file that cannot be read raises :class:`webots_vehicle.WorldError`."""
    return _native.controllers_cars()


def select(name: str) -> None:
    """Makes the controller of car ``name`` current (creating it, no library initialised, if
    the car has none yet). The first call loads the world for that car. A name the world has
    no car of raises ``ValueError`` listing the names; a world that cannot be loaded raises
    :class:`webots_vehicle.WorldError`."""
    names = [car for car, _ in cars()]
    if name not in names:
        raise ValueError(f"the world has no car named {name!r} (its cars: {', '.join(names)})")
    _native.controllers_select(name)


def current() -> Optional[str]:
    """The name of the car of the current controller; None before a world is loaded or for a
    DifferentialWheels robot."""
    return _native.controllers_current()
