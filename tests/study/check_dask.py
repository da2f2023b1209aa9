"""The study on a Dask cluster gives the same results as the local run: a LocalCluster (a real scheduler and
worker processes on this machine) runs the --quick cases through scripts/study.sh --dask, and every column of
runs.csv but the measured times (wall and CPU) must equal study.quick's byte for byte (the core is deterministic).
"""

import csv
import os
import subprocess
import sys

from distributed import LocalCluster


def rows(path):
    with open(path) as f:
        return [{k: v for k, v in r.items() if not k.endswith("_s_per_sim_s")} for r in csv.DictReader(f)]


def main():
    study_sh, local_out, dask_out = sys.argv[1:4]
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
