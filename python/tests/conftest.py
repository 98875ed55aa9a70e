"""Fixtures of the package's tests: the repository, a clean Webots session per test, the C
API's staged libraries and the `vehicle-sim` command (both built with cargo from this
repository)."""

import os
import subprocess
import sys
from pathlib import Path
from typing import Optional

import pytest

ROOT = Path(__file__).resolve().parents[2]
TESTS = Path(__file__).resolve().parent
WORLDS = TESTS / "worlds"


@pytest.fixture
def webots(monkeypatch):
    """A fresh controller process state: no world loaded, no Robot created, VEHICLE_WORLD
    unset (tests set it with ``monkeypatch.setenv``). Cleans up afterwards."""
    import controller
    from webots_vehicle import _native

    def reset():
        _native.wb_robot_cleanup()
        controller.Robot.created = None

    monkeypatch.delenv("VEHICLE_WORLD", raising=False)
    reset()
    yield monkeypatch
    reset()


def run_controller(
    script: Path, world: str, timeout: float = 120.0, out: Optional[Path] = None
) -> subprocess.CompletedProcess:
    """Runs the controller ``script`` as Webots would start it, in its own process with
    ``VEHICLE_WORLD=world`` (and ``VEHICLE_OUT=out`` if given)."""
    env = dict(os.environ, VEHICLE_WORLD=world)
    env.pop("VEHICLE_OUT", None)
    if out is not None:
        env["VEHICLE_OUT"] = str(out)
    return subprocess.run(
        [sys.executable, str(script)], env=env, capture_output=True, text=True, timeout=timeout
    )


def _cargo(*args: str) -> subprocess.CompletedProcess:
    cargo = os.environ.get("CARGO", "cargo")
    out = subprocess.run(
        [cargo, *args, "--manifest-path", str(ROOT / "Cargo.toml")],
        capture_output=True,
        text=True,
    )
    assert out.returncode == 0, f"cargo {' '.join(args)} failed:\n{out.stderr}"
    return out


@pytest.fixture(scope="session")
def staged_capi(tmp_path_factory) -> Path:
    """``capi/stage.sh --debug`` into a temporary prefix; the directory of libcar.so and
    libdriver.so."""
    prefix = tmp_path_factory.mktemp("capi-prefix")
    out = subprocess.run(
        ["bash", str(ROOT / "capi" / "stage.sh"), "--debug", str(prefix)],
        capture_output=True,
        text=True,
    )
    assert out.returncode == 0, f"capi/stage.sh failed:\n{out.stdout}{out.stderr}"
    return prefix / "lib" / "controller"


@pytest.fixture(scope="session")
def vehicle_sim() -> Path:
    """The `vehicle-sim` command of this repository (dev profile, as `cargo test` builds it)."""
    _cargo("build", "--quiet", "-p", "sim", "--bin", "vehicle-sim")
    meta = _cargo("metadata", "--no-deps", "--format-version", "1")
    import json

    target = Path(json.loads(meta.stdout)["target_directory"])
    return target / "debug" / "vehicle-sim"
