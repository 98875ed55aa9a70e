"""Webots' ``Supervisor`` (``controller.Supervisor``): placing the world's cars and bodies."""

from typing import Optional

from webots_vehicle import _native

from .node import Node
from .robot import Robot


class Supervisor(Robot):
    """A robot with supervisor rights (Webots: ``controller.Supervisor``): Webots' subset for
    placing things (COMPATIBILITY.md): :meth:`getFromDef` finds a car (DEF = its ``name``) or
    a dynamic body (``body[1]``, ``body[2]``, ... in the world file's order), whose
    ``translation``/``rotation`` fields and velocity it reads and sets, and
    :meth:`simulationReset` puts the world back as loaded."""

    def getFromDef(self, name: str) -> Optional[Node]:
        """The node of DEF name ``name``, None if there is none."""
        found = _native.supervisor_node_from_def(str(name))
        return None if found is None else Node(found[0], found[1], str(name))

    def simulationReset(self) -> None:
        """The world back as loaded: time 0, every car and body where the world file put
        them, the other cars' programmes from their start. The controller goes on, its
        devices enabled as it left them."""
        _native.supervisor_simulation_reset()
