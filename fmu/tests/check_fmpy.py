"""The FMU as FMPy (a tool ECU engineers use) sees it: the model description validates, a
throttle/steering/brake input table simulates, the outputs follow the commands and equal, to
the last printed digit, vehicle-sim's run of the same commands as a world-file programme, and a
call in the wrong order is an error with a message through the FMI logger, not a crash. For
FMI 2.0 and 3.0 FMUs alike.

Usage: python fmu/tests/check_fmpy.py CAR.fmu [VEHICLE_SIM]
  (FMPy from PyPI; .ci/run installs it. With VEHICLE_SIM, the path of the vehicle-sim
  executable, the FMU's run is compared with vehicle-sim's telemetry.csv.)
"""

import csv
import math
import subprocess
import sys
import tempfile
import zipfile
from pathlib import Path

import numpy as np
from fmpy import calloc, extract, free, read_model_description, simulate_fmu
from fmpy.fmi2 import (
    FMU2Slave,
    fmi2CallbackAllocateMemoryTYPE,
    fmi2CallbackFreeMemoryTYPE,
    fmi2CallbackFunctions,
    fmi2CallbackLoggerTYPE,
)
from fmpy.fmi3 import FMU3Slave
from fmpy.validation import validate_fmu

# The commands of the input table below as a vehicle-sim programme: the same instants, the
# same values (the FMU hands inputs over at the communication point, right-continuous, as a
# programme issues its step at its `at`).
PROGRAMME = """
[[vehicle.programme]]
at = 0.0
throttle = 1.0
gear = 1
[[vehicle.programme]]
at = 2.0
throttle = 0.0
steering_angle = 0.1
[[vehicle.programme]]
at = 4.0
brake_intensity = 0.5
"""


def printed(value: float) -> float:
    """`value` as vehicle-sim's telemetry.csv prints it: rounded half away from zero to six
    decimals (sim::telemetry's `cell`)."""
    scaled = abs(value) * 1e6
    return math.copysign(math.floor(scaled + 0.5), value) / 1e6 + 0.0


def compare_with_vehicle_sim(path: str, vehicle_sim: str, result) -> int:
    """Runs the FMU's own world with PROGRAMME through vehicle-sim and compares every sample;
    returns the number of values compared."""
    with zipfile.ZipFile(path) as z:
        world = z.read("resources/world.toml").decode()
    with tempfile.TemporaryDirectory() as tmp:
        world_file = Path(tmp) / "world.toml"
        world_file.write_text(world + PROGRAMME)
        out = Path(tmp) / "out"
        subprocess.run(
            [vehicle_sim, "--world", str(world_file), "--scenario", "programme",
             "--duration", "6", "--out", str(out)],
            check=True, stdout=subprocess.DEVNULL,
        )
        with open(out / "telemetry.csv", newline="") as f:
            rows = {round(float(r["time_s"]), 6): r for r in csv.DictReader(f)}
    columns = [("x", "x_m", 1.0), ("y", "y_m", 1.0), ("yaw", "yaw_rad", 1.0),
               ("speed", "speed_kmh", 3.6), ("engine_speed", "rpm", 1.0),
               ("engaged_gear", "gear", 1.0)]
    compared = 0
    for i, t in enumerate(result["time"]):
        row = rows.get(round(float(t), 6))
        assert row is not None, f"vehicle-sim has no row at t = {t} s"
        for output, column, factor in columns:
            fmu = printed(float(result[output][i]) * factor)
            cell = row[column]
            # No rpm or gear before the driver's first step (an empty cell); the FMU's outputs
            # read 0 where the quantity does not exist (fmu/README.md).
            native = float(cell) if cell or column not in ("rpm", "gear") else 0.0
            assert fmu == native, f"{output} at t = {t} s: FMU {fmu}, vehicle-sim {native}"
            compared += 1
    return compared


def main(path: str, vehicle_sim: str | None) -> None:
    problems = validate_fmu(path)
    assert not problems, problems
    md = read_model_description(path)
    assert md.fmiVersion in ("2.0", "3.0") and md.coSimulation is not None

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
    compared = compare_with_vehicle_sim(path, vehicle_sim, result) if vehicle_sim else 0

    # A doStep before initialisation: an error status and the reason in the logger.
    messages = []
    unzipped = extract(path)
    if md.fmiVersion == "2.0":

        def logger(env, name, status, category, message):
            messages.append((status, message.decode()))

        fmu = FMU2Slave(
            guid=md.guid,
            unzipDirectory=unzipped,
            modelIdentifier=md.coSimulation.modelIdentifier,
            instanceName="order",
        )
        callbacks = fmi2CallbackFunctions()
        callbacks.logger = fmi2CallbackLoggerTYPE(logger)
        callbacks.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        callbacks.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        fmu.instantiate(callbacks=callbacks, loggingOn=True)
    else:

        def logger(env, status, category, message):
            messages.append((status, message.decode()))

        fmu = FMU3Slave(
            guid=md.guid,
            unzipDirectory=unzipped,
            modelIdentifier=md.coSimulation.modelIdentifier,
            instanceName="order",
        )
        fmu.instantiate(loggingOn=True, logMessage=logger)
    try:
        fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=0.01)
    except Exception:
        pass
    else:
        raise AssertionError("doStep before initialisation was accepted")
    function = "fmi2DoStep" if md.fmiVersion == "2.0" else "fmi3DoStep"
    assert any(status == 3 and function in text for status, text in messages), messages
    fmu.freeInstance()
    print(
        f"FMPy check passed (FMI {md.fmiVersion}): {len(t)} samples, final x = "
        f"{result['x'][-1]:.3f} m"
        + (f"; {compared} values equal vehicle-sim's to the printed digit" if compared else "")
    )


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else None)
