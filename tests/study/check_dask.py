"""The study on a Dask cluster gives the same results as the local run: a LocalCluster (a real scheduler and
worker processes on this machine) runs the --quick cases through scripts/study.sh --dask, and every column of
runs.csv but the measured times (wall and CPU, their spread and the runs taken) must equal study.quick's byte for
byte (the core is deterministic). A scheduler that cannot be reached ends the study in one line and exit status 2,
within seconds.
"""

import csv
import os
import subprocess
import sys
import tempfile
import time

from distributed import LocalCluster


MEASURED = {"cpu_spread", "runs"}  # besides the times: how often a case ran, and its times' spread


def rows(path):
    with open(path) as f:
        return [{k: v for k, v in r.items() if not k.endswith("_s_per_sim_s") and k not in MEASURED}
                for r in csv.DictReader(f)]


def unreachable_scheduler(study_sh):
    """A scheduler nobody listens at (port 9, discard): one line on stderr, exit 2, in well under 30 s."""
    with tempfile.TemporaryDirectory() as out:
        start = time.monotonic()
        done = subprocess.run(["bash", study_sh, "--quick", "--no-plots", "--dask", "tcp://127.0.0.1:9", "--out", out],
                              capture_output=True, text=True)
        took = time.monotonic() - start
    lines = done.stderr.strip().splitlines()
    if done.returncode != 2 or len(lines) != 1 or took > 20:
        print(f"FAIL: an unreachable scheduler gave exit {done.returncode} after {took:.0f} s, stderr:")
        print(done.stderr)
        sys.exit(1)
    print(f"an unreachable scheduler: exit 2 after {took:.1f} s: {lines[0]}")


def main():
    study_sh, local_out, dask_out = sys.argv[1:4]
    unreachable_scheduler(study_sh)
    with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None) as cluster:
        subprocess.run(["bash", study_sh, "--quick", "--no-plots", "--dask", cluster.scheduler_address,
                        "--out", dask_out], check=True)
    local, remote = rows(os.path.join(local_out, "runs.csv")), rows(os.path.join(dask_out, "runs.csv"))
    if not local or local != remote:
        print("FAIL: the Dask run's rows differ from the local run's")
        for a, b in zip(local, remote):
            if a != b:
                print(" local", a, "\n dask ", b)
        sys.exit(1)
    summary = open(os.path.join(dask_out, "summary.md")).read()
    if "Dask scheduler" not in summary:
        print("FAIL: summary.md does not say the cases ran on Dask")
        sys.exit(1)
    print(f"{len(local)} rows equal (errors and settings) between the local and the Dask run")


if __name__ == "__main__":
    main()
