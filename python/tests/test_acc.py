"""The adaptive cruise controller example (examples/acc/acc.py) in sim/worlds/acc.toml: the lead
car drives at 20 m/s, slows to 15 m/s at 20 s and stops from 40 s; the follower keeps its time
gap with the radar alone and stops behind it without touching it."""

import json

from conftest import ROOT, run_controller


def test_acc_example_keeps_the_time_gap(tmp_path):
    world = str(ROOT / "sim" / "worlds" / "acc.toml")
    out = run_controller(ROOT / "examples" / "acc" / "acc.py", world, out=tmp_path)
    assert out.returncode == 0, out.stderr
    assert out.stderr == ""
    log = [[float(x) for x in line.split()[1:]] for line in out.stdout.splitlines()]
    # One line per 0.5 s; the step that ends the 60 s returns -1 before the last.
    assert len(log) == 119
    # TIME_GAP 1.5 s beyond STANDSTILL 7 m, within 10 % over the last 5 s before each of the
    # lead car's speed steps.
    for t, v, d in log:
        if 15.0 <= t <= 20.0 or 35.0 <= t <= 40.0:
            gap = (d - 7.0) / v
            assert abs(gap - 1.5) <= 0.15, (t, v, d, gap)
    # Stopped behind it: between STANDSTILL and where the command falls below CREEP
    # (7 + 0.5/0.4 m), as the radar measures it (1.5 m: three standard deviations of the
    # Delphi ESR's range noise); the cars never touched.
    t, v, d = log[-1]
    assert t == 59.5 and abs(v) < 0.1
    assert 7.0 - 1.5 <= d <= 8.25 + 1.5
    metrics = json.loads((tmp_path / "metrics.json").read_text())
    run = metrics["scenarios"]["controller"]
    assert run["touched"] is False and run["min_gap_m"] > 5.0
