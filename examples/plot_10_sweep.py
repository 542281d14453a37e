"""
A design sweep, on local processes and on a dask cluster
========================================================

A designer rarely wants one pocket: rather a map of how the pressure rise depends on the rubber, the
initial pressure and the force. ``pocket.apps.sweep`` solves a grid of (alpha, Phat_I, Fhat) on any
``concurrent.futures`` executor, one task per curve (a rubber and an initial pressure, solved by
continuation through its forces), and writes one CSV row per point. This example runs the same small
grid twice: on two local processes, and on a dask.distributed cluster (here a ``LocalCluster`` of two
workers in this process; on a real cluster, its scheduler's address), and compares the two files.

Run it as a script: ``python examples/plot_10_sweep.py``.
"""

# %%
# The grid, in the model's units: two rubbers (alpha = C2/C1), three initial pressures, four forces,
# so six curves of four points each.
import csv
import pathlib
import tempfile

import matplotlib.pyplot as plt
from dask.distributed import LocalCluster

from pocket.apps.sweep.cluster import connect
from pocket.apps.sweep.grid import run_sweep
from pocket.apps.sweep.workers import local_executor, stop

ALPHAS = (0.0, 47 / 160)  # C2/C1
PRESSURES = (0.1, 0.2, 0.31)  # Phat_I
FORCES = (0.1, 0.3, 0.6, 1.0)  # Fhat


def read(path: pathlib.Path) -> list[dict]:
    """The sweep file's rows, numbers as floats where they are numbers."""
    def number(text):
        try:
            return float(text)
        except ValueError:
            return text

    with path.open(newline="") as handle:
        return [{k: number(v) for k, v in row.items()} for row in csv.DictReader(handle)]


# %%
# The local executor is a pool of processes that die with this one (``local_executor``; ``stop`` ends
# it). The dask executor comes from ``connect``, which waits for a worker and checks that the workers
# run this pocket before it sends any task; closing it closes its client, and the cluster is closed
# after it. Both run the same function on each curve, so the two files must hold the same numbers.
def main(out: pathlib.Path) -> dict:
    """Run the grid on local processes and on a dask cluster, writing ``local.csv`` and ``dask.csv`` into
    ``out``; print a summary; returns ``{"local": rows, "dask": rows}`` (each a list of dicts)."""
    files = {"local": out / "local.csv", "dask": out / "dask.csv"}
    executor = local_executor(2)
    try:
        run_sweep(files["local"], ALPHAS, PRESSURES, FORCES, executor)
    finally:
        stop(executor)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=False, dashboard_address=None) as cluster:
        executor = connect(cluster.scheduler_address)
        try:
            run_sweep(files["dask"], ALPHAS, PRESSURES, FORCES, executor)
        finally:
            executor.shutdown()
    rows = {name: read(path) for name, path in files.items()}
    same = all(a == b for a, b in zip(rows["local"], rows["dask"], strict=True))
    print(f"{len(rows['local'])} points ({len(ALPHAS)} rubbers x {len(PRESSURES)} pressures x {len(FORCES)} "
          f"forces), status: {sorted({r['status'] for r in rows['local']})}")
    print(f"local processes and the dask cluster wrote the same rows: {same}")
    print("P/P_I of each curve at the forces Fhat = " + ", ".join(f"{f:g}" for f in FORCES) + ":")
    for alpha in ALPHAS:
        for p in PRESSURES:
            curve = [r for r in rows["dask"] if r["alpha"] == alpha and r["pressure_initial"] == p]
            print(f"  alpha = {alpha:.4f}, Phat_I = {p:<4g}: " + " ".join(f"{r['pressure_ratio']:.5f}" for r in curve))
    return rows


# %%
# The figure: the pressure rise against the force for each curve of the grid. A softer start (lower
# Phat_I) gives a larger rise for the same Fhat; the neo-Hookean rubber (alpha = 0) and the paper's
# silicone differ little at these loads.
def draw(rows: dict):
    """P/P_I against Fhat, one line per (alpha, Phat_I)."""
    fig, ax = plt.subplots(figsize=(6.5, 4), layout="constrained")
    for alpha, style in zip(ALPHAS, ("--", "-"), strict=True):
        for p in PRESSURES:
            curve = [r for r in rows["dask"] if r["alpha"] == alpha and r["pressure_initial"] == p]
            ax.plot([r["force"] for r in curve], [r["pressure_ratio"] for r in curve], style, marker="o", ms=3,
                    label=rf"$\alpha$ = {alpha:.3g}, $\hat P_I$ = {p:g}")
    ax.set_xlabel(r"$F/(P_I \pi R^2)$")
    ax.set_ylabel("$P/P_I$")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, ncol=2)
    return fig


# %%
# Run it; the sweep files live in a temporary folder.
if __name__ == "__main__":
    with tempfile.TemporaryDirectory() as folder:
        draw(main(pathlib.Path(folder)))
    plt.show()
