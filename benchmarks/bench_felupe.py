"""FElupe's axisymmetric solid against pocket's membrane on the headline pocket (T/R = 0.0125).

    python benchmarks/bench_felupe.py        # needs `pip install felupe tensortrax`; skips without them

FElupe is a peer here, never a dependency of pocket. Prints: the FElupe model's mesh convergence on the
inflated pocket (elements along the radius, layers through the thickness), its inflated H0, mid-surface
pole height and volume beside the membrane's (``pocket.shooting.inflate``), P/P_I and H/H0 under the
plate at a few forces beside ``pocket.shooting.compress``, the differences (absolute, and over T/R:
the membrane's error is O(T/R)), the wall times (medians; the load average printed with them), and
``pocket.solid``'s numbers where that model is installed.
"""

from __future__ import annotations

import importlib.util
import os
import sys

from timing import median_time

from pocket import shooting

FORCES = (0.05, 0.19, 0.5)
#: the mesh the comparison uses (elements along the radius, layers). Measured by ``convergence`` (load 3 on
#: 2 cores): radial refinement 64 -> 128 moves V by 2e-6 (relative), H0 by 4e-7 R, and P/P_I at Fhat = 0.19
#: by 2e-5; through the thickness the clamp's corners converge at order ~1 (V moves 2.3e-4 from two layers
#: to four, 1.3e-4 from four to eight), so four layers leave V ~3e-4 (relative, 0.02 T/R) and H0 ~3e-5 R
#: below the converged solid: small beside the membrane's differences (0.9 T/R in V), at a quarter of the
#: eight-layer cost.
MESH = (64, 4)


def _run_inflation(elements, layers):
    import felupe_pocket as fp

    return fp.inflate(fp.build(elements=elements, layers=layers))


def convergence():
    """Inflated H0 and V on refined meshes, each against the finest: FElupe's own discretisation error."""
    import felupe_pocket as fp

    meshes = [(32, 4), (64, 4), (128, 4), (64, 2), (64, 8), (128, 8)]
    rows = {mesh: _run_inflation(*mesh) for mesh in meshes}
    best = rows[(128, 8)]
    print(f"FElupe mesh convergence, inflated at Phat_I = {fp.PHAT} (differences from 128 x 8):")
    print(f"  {'elements x layers':>18s} {'H0':>12s} {'dH0':>9s} {'V':>12s} {'dV/V':>9s} {'|V - V_mid|/V':>14s}")
    for (n, k), s in rows.items():
        print(f"  {f'{n} x {k}':>18s} {s['height']:12.8f} {s['height'] - best['height']:9.1e} {s['volume']:12.8f} "
              f"{s['volume'] / best['volume'] - 1:9.1e} {abs(s['volume'] - s['volume_mid']) / s['volume']:14.1e}")
    return rows


def main():
    if importlib.util.find_spec("felupe") is None or importlib.util.find_spec("tensortrax") is None:
        print("bench_felupe: felupe (and tensortrax) not installed; skipped")
        return 0
    sys.path.insert(0, os.path.dirname(__file__))
    import felupe_pocket as fp

    t = fp.THICKNESS
    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    convergence()

    m = fp.build(elements=MESH[0], layers=MESH[1])
    s = fp.inflate(m)
    t_inf = median_time(lambda: _run_inflation(*MESH), 3)
    curve = fp.compress(m, s, FORCES)
    ref = shooting.inflate(fp.ALPHA, fp.PHAT, rtol=1e-12)
    print(f"\nheadline pocket: alpha = {fp.ALPHA:.6g}, Phat_I = {fp.PHAT}, T/R = {t}; FElupe mesh "
          f"{MESH[0]} x {MESH[1]} (Q2 u-p-J), membrane = pocket.shooting")
    print("  inflated (heights from the flat mid-plane; FElupe's V from the flat lower face, V_mid from the "
          "mid-plane):")
    print(f"  {'':22s} {'FElupe':>12s} {'membrane':>12s} {'difference':>11s} {'/ (T/R)':>9s}")
    for name, mine, theirs in (("H0 (upper surface)", s["height"], ref.height),
                               ("H0 (mid-surface)", s["height_mid"], ref.height),
                               ("V (lower surface)", s["volume"], ref.volume),
                               ("V_mid (mid-surface)", s["volume_mid"], ref.volume)):
        print(f"  {name:22s} {mine:12.8f} {theirs:12.8f} {mine - theirs:11.2e} {(mine - theirs) / t:9.3f}")
    print("  compressed at fixed liquid volume (H = the plate's height):")
    print(f"  {'Fhat':>6s} {'P/P_I FElupe':>13s} {'membrane':>10s} {'diff %':>8s} {'/ (T/R)':>8s} "
          f"{'H/H0 FElupe':>12s} {'membrane':>10s} {'diff %':>8s} {'/ (T/R)':>8s}")
    for row in curve:
        c = shooting.compress(fp.ALPHA, fp.PHAT, row["force"])
        dp = row["pressure_ratio"] / c.pressure_ratio - 1
        dh = row["height_ratio"] / c.height_ratio - 1
        print(f"  {row['force']:6.3f} {row['pressure_ratio']:13.7f} {c.pressure_ratio:10.7f} {100 * dp:8.3f} "
              f"{dp / t:8.3f} {row['height_ratio']:12.7f} {c.height_ratio:10.7f} {100 * dh:8.3f} {dh / t:8.3f}")

    t_mem = median_time(lambda: shooting.inflate(fp.ALPHA, fp.PHAT), 11)
    t_cmem = median_time(lambda: shooting.compression_curve(fp.ALPHA, fp.PHAT, FORCES), 11)
    print(f"wall times (load average now {os.getloadavg()[0]:.1f}):")
    print(f"  FElupe inflation         {t_inf:8.2f} s (median of 3; {s['iterations']} Newton iterations)")
    print(f"  FElupe {len(FORCES)}-force curve     {curve[-1]['seconds']:8.2f} s (one run; "
          f"{curve[-1]['iterations'] - s['iterations']} Newton iterations in the secant loops)")
    print(f"  membrane inflation       {t_mem * 1e3:8.2f} ms, {len(FORCES)}-force curve {t_cmem * 1e3:.2f} ms")

    if importlib.util.find_spec("pocket.solid") is not None:
        from pocket import solid

        si = solid.inflate(fp.ALPHA, fp.PHAT, thickness_ratio=t)
        sc = solid.compression_curve(fp.ALPHA, fp.PHAT, FORCES, thickness_ratio=t)
        t_solid = median_time(lambda: solid.compression_curve(fp.ALPHA, fp.PHAT, FORCES, thickness_ratio=t), 3)
        print("pocket.solid against FElupe (differences / (T/R)):")
        print(f"  H0 {si.height:.8f} ({(si.height - s['height']) / t:+.4f}), "
              f"H0 mid {si.extra['height_mid']:.8f} ({(si.extra['height_mid'] - s['height_mid']) / t:+.4f}), "
              f"V {si.volume:.8f} ({(si.volume - s['volume']) / t:+.4f})")
        for row, c in zip(curve, sc, strict=True):
            dp = c.pressure_ratio / row["pressure_ratio"] - 1
            dh = c.height_ratio / row["height_ratio"] - 1
            print(f"  Fhat {row['force']:.3f}: P/P_I {c.pressure_ratio:.7f} ({dp / t:+.4f}), "
                  f"H/H0 {c.height_ratio:.7f} ({dh / t:+.4f})")
        print(f"  pocket.solid {len(FORCES)}-force curve {t_solid:.2f} s (median of 3)")
    else:
        print("pocket.solid: not installed here; skipped")
    return 0


if __name__ == "__main__":
    sys.exit(main())
