"""The FMU as FMPy (a tool ECU engineers use) sees it: the model description validates, a
throttle/steering/brake input table simulates, the outputs follow the commands, and a call in
the wrong order is an error with a message through the FMI logger, not a crash.

Usage: python fmu/tests/check_fmpy.py CAR.fmu   (FMPy from PyPI; .ci/run installs it)
"""

import sys

import numpy as np
from fmpy import calloc, extract, free, read_model_description, simulate_fmu
from fmpy.fmi2 import (
    FMU2Slave,
    fmi2CallbackAllocateMemoryTYPE,
    fmi2CallbackFreeMemoryTYPE,
    fmi2CallbackFunctions,
    fmi2CallbackLoggerTYPE,
)
from fmpy.validation import validate_fmu


def main(path: str) -> None:
    problems = validate_fmu(path)
    assert not problems, problems
    md = read_model_description(path)
    assert md.fmiVersion == "2.0" and md.coSimulation is not None

    # Full throttle in first gear for 2 s, then 0.1 rad of steering (right) with the throttle
    # off, then half brake: a repeated time is a step in the table.
    signals = np.array(
        [
            (0.0, 1.0, 0.0, 0.0, 1),
            (2.0, 1.0, 0.0, 0.0, 1),
            (2.0, 0.0, 0.1, 0.0, 1),
            (4.0, 0.0, 0.1, 0.0, 1),
            (4.0, 0.0, 0.1, 0.5, 1),
            (6.0, 0.0, 0.1, 0.5, 1),
        ],
        dtype=[
            ("time", np.float64),
            ("throttle", np.float64),
            ("steering_angle", np.float64),
            ("brake_intensity", np.float64),
            ("gear", np.int32),
        ],
    )
    result = simulate_fmu(
        path,
        start_time=0.0,
        stop_time=6.0,
        step_size=0.01,
        input=signals,
        output=["x", "y", "yaw", "speed", "engine_speed", "engaged_gear"],
    )
    t = result["time"]

    def at(seconds: float) -> int:
        return int(np.argmin(np.abs(t - seconds)))

    assert result["speed"][at(2.0)] > 3.0, result["speed"][at(2.0)]
    assert result["engaged_gear"][at(1.0)] == 1
    assert result["engine_speed"][at(1.0)] > 0.0
    # Positive steering turns right: the heading falls.
    assert result["yaw"][at(4.0)] < result["yaw"][at(2.0)] - 0.05
    # Braking slows the car.
    assert result["speed"][at(6.0)] < result["speed"][at(4.0)] - 1.0
    assert all(np.isfinite(result[name]).all() for name in ("x", "y", "yaw", "speed"))

    # A doStep before initialisation: an error status and the reason in the logger.
    messages = []

    def logger(env, name, status, category, message):
        messages.append((status, message.decode()))

    fmu = FMU2Slave(
        guid=md.guid,
        unzipDirectory=extract(path),
        modelIdentifier=md.coSimulation.modelIdentifier,
        instanceName="order",
    )
    callbacks = fmi2CallbackFunctions()
    callbacks.logger = fmi2CallbackLoggerTYPE(logger)
    callbacks.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
    callbacks.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
    fmu.instantiate(callbacks=callbacks, loggingOn=True)
    try:
        fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=0.01)
    except Exception:
        pass
    else:
        raise AssertionError("doStep before initialisation was accepted")
    assert any(status == 3 and "fmi2DoStep" in text for status, text in messages), messages
    fmu.freeInstance()
    print(f"FMPy check passed: {len(t)} samples, final x = {result['x'][-1]:.3f} m")


if __name__ == "__main__":
    main(sys.argv[1])
