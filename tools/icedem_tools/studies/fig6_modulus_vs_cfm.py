"""The seed paper's Figure 6 for this solver: the elastic modulus a floating
plate of ice elements shows in the plate-deflection test, against the joints'
constraint force mixing (fracture.cfm), for several element sizes.

Runs `icedem run scenarios/validation/plate_deflection_27_015.toml` once per
(element size, CFM) with --set, reads the `validation` block of each summary,
and writes a PNG and a CSV. Usage:

    scripts/fig6_modulus_vs_cfm.py [--icedem build/dem/icedem] [--out docs/validation]
                                   [--iterations 50] [--joint-iterations 0] [--plate 2.7]

--iterations sets solver.iterations, --joint-iterations fracture.joint_iterations
(0: the joints get solver.iterations too). --replot redraws the PNG from the CSV
of the same settings without running anything.
"""
import argparse
import csv
import os
import sys
import tempfile

from ..runs import output_guard, runner

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from ..runs.spec import ROOT
SCENARIO = os.path.join(ROOT, "scenarios", "validation", "plate_deflection_27_015.toml")


def run(icedem, sets, work):
    """The plate case's validation block at these settings (one run, tools/icedem_tools/runs/runner.py)."""
    r = runner.execute(SCENARIO, os.path.join(work, "plate"), sets, icedem=icedem)
    if not r.ok:
        sys.exit(f"fig6_modulus_vs_cfm: {' '.join(r.command)} failed: {r.error}")
    return r.summary["validation"]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--icedem", default=os.path.join(ROOT, "build", "dem", "icedem"))
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "validation"))
    ap.add_argument("--iterations", type=int, default=50)
    ap.add_argument("--joint-iterations", type=int, default=0)
    ap.add_argument("--erp", type=float, default=0.8, help="fracture.erp (the scenarios use 0.8)")
    ap.add_argument("--replot", action="store_true")
    ap.add_argument("--plate", type=float, default=2.7, help="nominal plate side, m (rounded to whole elements)")
    args = ap.parse_args(argv)
    output_guard.guard([("--out", args.out, output_guard.DIRECTORY)])
    os.makedirs(args.out, exist_ok=True)

    sizes = [0.10, 0.15, 0.20]
    cfms = [1e-10, 1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 1e-1]
    if args.erp < 0.5:
        cfms = [1e-10, 1e-4, 3e-4, 1e-3, 2e-3, 3e-3, 1e-2, 3e-2]
    tag = f"{args.iterations}it" + (f"_joints{args.joint_iterations}it" if args.joint_iterations else "")
    tag += f"_erp{args.erp:g}" if args.erp != 0.8 else ""
    if abs(args.plate - 2.7) > 1e-9:
        tag += f"_{args.plate:g}m"
    stem = os.path.join(args.out, f"fig6_modulus_vs_cfm_{tag}")
    if args.replot:
        with open(stem + ".csv") as f:
            rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    else:
        rows = []
        with tempfile.TemporaryDirectory() as work:
            for le in sizes:
                plate = round(args.plate / le) * le
                for cfm in cfms:
                    v = run(args.icedem, [f"fracture.element_size={le}", f"validation.plate_size={plate:.4f}",
                                          f"fracture.cfm={cfm}", f"solver.iterations={args.iterations}",
                                          f"fracture.joint_iterations={args.joint_iterations}",
                                          f"fracture.erp={args.erp}"], work)
                    rows.append({"element_size_m": le, "plate_m": plate, "cfm": cfm,
                                 "w0_mm_per_N": v["value"], "reference_mm_per_N": v["reference"],
                                 "E_MPa": v["elastic_modulus_MPa"]})
                    print(f"L_e {le:.2f} m, plate {plate:.2f} m, cfm {cfm:g}: w0/P {v['value']:.4f} mm/N, "
                          f"E {v['elastic_modulus_MPa']:.1f} MPa", flush=True)
        with open(stem + ".csv", "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for le in sizes:
        pts = [r for r in rows if r["element_size_m"] == le]
        ax.loglog([r["cfm"] for r in pts], [r["E_MPa"] for r in pts], "o-", label=f"L_e = {le:.2f} m")
    ax.axhline(60.0, color="k", ls="--", lw=1, label="E = 60 MPa (Table 3)")
    ax.set_xlabel("joint CFM (Bullet units, fracture.cfm)")
    ax.set_ylabel("elastic modulus from plate deflection, MPa")
    joints = (f", joints {args.joint_iterations}" if args.joint_iterations else "") + f", ERP {args.erp:g}"
    ax.set_title(f"Plate deflection, ~{args.plate} m plate, {args.iterations} PGS iterations{joints}", fontsize=10)
    ax.legend()
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(stem + ".png", dpi=110)
    print(f"wrote {stem}.png" + ("" if args.replot else f" and {stem}.csv"))


if __name__ == "__main__":
    main()
