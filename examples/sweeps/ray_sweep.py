"""A sweep spread over a Ray cluster: one Ray task per group of case indices, the rows written
into ``results.csv`` in case order, byte for byte what ``vehicle-sim sweep`` writes.

    pip install ./python ray
    python examples/sweeps/ray_sweep.py examples/sweeps/brake.toml --out ray-out           # local Ray
    python examples/sweeps/ray_sweep.py examples/sweeps/brake.toml --out ray-out --address auto  # a cluster

On a cluster, every node needs the package (``pip install ./python``) and the sweep file and
its world at the same path (a shared file system), or ship them with the job:
``ray job submit --runtime-env-json '{"working_dir": "."}' -- python examples/sweeps/ray_sweep.py
examples/sweeps/brake.toml --out ray-out --address auto``.

The driver keeps at most ``--in-flight`` tasks running and holds the rows that finish before
their turn until the rows before them are written, so its memory does not grow with the
number of cases; each worker loads the sweep once and runs its cases with the GIL released.
"""

import argparse
import os
import sys
from typing import Dict, List

import ray

import webots_vehicle as wv

# The sweeps a worker process has loaded, by path: loading checks the sweep against its world
# and runs the scenario for one step to find the columns, which is worth doing once.
_LOADED: Dict[str, "wv.Sweep"] = {}


@ray.remote
def run_cases(sweep_file: str, indices: List[int]) -> str:
    """The ``results.csv`` lines of the cases ``indices`` of ``sweep_file``."""
    sweep = _LOADED.get(sweep_file)
    if sweep is None:
        sweep = _LOADED.setdefault(sweep_file, wv.Sweep(sweep_file))
    return "".join(sweep.run_case_csv(i) for i in indices)


def run(sweep_file: str, out: str, cases_per_task: int = 8, in_flight: int = 0) -> int:
    """Runs every case of ``sweep_file`` on the Ray cluster ``ray.init`` connected to and
    writes ``out/results.csv``; returns the number of cases. ``in_flight`` tasks at most run
    at once (0: four per CPU of the cluster)."""
    sweep_file = os.path.abspath(sweep_file)
    sweep = wv.Sweep(sweep_file)
    n = len(sweep)
    chunks = [list(range(k, min(k + cases_per_task, n))) for k in range(0, n, cases_per_task)]
    limit = in_flight or 4 * max(1, int(ray.cluster_resources().get("CPU", 1)))
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "results.csv"), "w", encoding="utf-8", newline="") as f:
        f.write(sweep.csv_header())
        running = {}  # Ray reference -> chunk number
        early = {}  # chunk number -> its lines, finished before their turn
        submitted = written = 0
        while written < len(chunks):
            while submitted < len(chunks) and len(running) < limit:
                running[run_cases.remote(sweep_file, chunks[submitted])] = submitted
                submitted += 1
            done, _ = ray.wait(list(running), num_returns=1)
            for ref in done:
                early[running.pop(ref)] = ray.get(ref)
            while written in early:
                f.write(early.pop(written))
                written += 1
    return n


def main(argv: List[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sweep", help="the sweep file")
    parser.add_argument("--out", required=True, help="output directory (results.csv)")
    parser.add_argument("--address", help="the Ray cluster (e.g. auto); default: a local Ray")
    parser.add_argument("--num-cpus", type=int, help="CPUs of a local Ray (default: all)")
    parser.add_argument("--cases-per-task", type=int, default=8)
    parser.add_argument("--in-flight", type=int, default=0)
    args = parser.parse_args(argv)
    if args.address:
        ray.init(address=args.address)
    else:
        ray.init(num_cpus=args.num_cpus, include_dashboard=False)
    n = run(args.sweep, args.out, args.cases_per_task, args.in_flight)
    print(f"{n} cases: {os.path.join(args.out, 'results.csv')}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
