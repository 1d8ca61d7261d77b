"""Run the validation scenarios (scenarios/validation/) and plot them:

  cantilever_015.png   seed paper Fig. 7 with a load ramp in air: the bending stress at the
                       root joint from the joint feedback and sigma' = 6 P l / (L_e T_e^2)
                       from the tip load, against time, up to the break; sigma_b = 36.4 kPa
  cantilever_floating_015.png  Fig. 7(a) as the paper ran it: the push force on the tip of
                       a floating beam pushed down at constant speed, its peak P_c at the
                       break, the fragment's buoyancy P_b after, and sigma' from eq. 6
  plate_deflection.png seed paper Fig. 6 as numbers: the centre deflection per unit load
                       of each plate scenario against Hertz's reference (x finite-plate
                       factor), with the tolerance band, and the inferred E
  validation.md        the table of every case: value, reference, error, passed

    scripts/validation_report.py [--icedem build/dem/icedem] [--out docs/validation] [--replot]

The run summaries are kept in OUT/validation_summaries.json; --replot redraws
the plots and the table from it without running anything.
"""
import argparse
import glob
import json
import os
import sys
import tempfile

from ..runs import output_guard, runner

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from ..runs.spec import ROOT


def run(icedem, scenario, work):
    """(name, summary) of one validation scenario (tools/icedem_tools/runs/runner.py)."""
    name = os.path.splitext(os.path.basename(scenario))[0]
    r = runner.execute(scenario, os.path.join(work, name), icedem=icedem)
    if not r.ok:
        sys.exit(f"validation_report: {name} failed: {r.error}")
    return name, r.summary


def run_all(icedem):
    results = []
    with tempfile.TemporaryDirectory() as work:
        for scenario in sorted(glob.glob(os.path.join(ROOT, "scenarios", "validation", "*.toml"))):
            name, s = run(icedem, scenario, work)
            results.append((name, s))
            v = s["validation"]
            print(f"{name}: {v['metric']} = {v['value']:.4g} (reference {v['reference']:.4g}), "
                  f"error {100 * v['rel_error']:+.1f} %, {'passed' if v['passed'] else 'FAILED'}, "
                  f"{s['wall_time_s']:.1f} s wall", flush=True)
    return results


def plot_floating_cantilever(name, s, out):
    v = s["validation"]
    h = v["history"]
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    ax.plot(h["time_s"], h["tip_load_N"], label="push force on the tip (reaction), N")
    ax.axhline(v["fragment_buoyancy_N"], color="tab:green", ls="--", lw=1,
               label=f"P_b = {v['fragment_buoyancy_N']:.2f} N, fragment buoyancy (0.5-1.5 s after)")
    ax.plot([v["time_of_failure_s"]], [v["load_at_failure_N"]], "rx", ms=10,
            label=f"P_c = {v['load_at_failure_N']:.2f} N: {v['failure_mode']} at joint {v['failed_joint']}; "
                  f"sigma' = {v['value']:.2f} kPa ({100 * v['rel_error']:+.1f} %)")
    ax.set_xlabel("time, s")
    ax.set_ylabel("force, N")
    ax.set_title(f"Floating cantilever pushed down ({name}), seed paper Fig. 7(a)", fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, name + ".png"), dpi=110)


def plot_cantilever(name, s, out):
    v = s["validation"]
    if v.get("floating"):
        plot_floating_cantilever(name, s, out)
        return
    h = v["history"]
    le, t = 0.15, 0.033  # the scenario's element size and thickness (set in its file)
    applied = [6 * p * v["lever_m"] / (le * t * t) / 1e3 for p in h["tip_load_N"]]
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    ax.plot(h["time_s"], applied, label="sigma' = 6 P l / (L_e T_e^2) from the tip load (eq. 6)")
    ax.plot(h["time_s"], h["root_joint_stress_kPa"], "--", label="root joint, from Bullet's joint feedback")
    ax.axhline(v["reference"], color="k", lw=1, ls=":", label=f"sigma_b = {v['reference']:.1f} kPa")
    ax.plot([v["time_of_failure_s"]], [v["value"]], "rx", ms=10,
            label=f"break: {v['failure_mode']} at joint {v['failed_joint']}, {v['value']:.2f} kPa "
                  f"({100 * v['rel_error']:+.2f} %)")
    ax.set_xlabel("time, s")
    ax.set_ylabel("bending stress at the root, kPa")
    ax.set_title(f"Cantilever test ({name}), seed paper Fig. 7")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, name + ".png"), dpi=110)


def plot_plates(plates, out):
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for i, (name, s) in enumerate(plates):
        v = s["validation"]
        ref, tol = v["reference"], v["tolerance"]
        ax.bar(i, v["value"], color="tab:blue" if v["passed"] else "tab:red", width=0.6)
        ax.errorbar(i, ref, yerr=tol * ref, fmt="k_", capsize=12, ms=30)
        top = max(v["value"], ref * (1 + tol))
        ax.text(i, top * 1.02, f"{100 * v['rel_error']:+.1f} %\nE {v['elastic_modulus_MPa']:.1f} MPa",
                ha="center", va="bottom", fontsize=8)
    ax.set_xticks(range(len(plates)))
    # size_element on one line, the variant (elastic, hexagon) under it: the names stay apart
    ax.set_xticklabels([n.replace("plate_deflection_", "").replace("5_", "5\n").replace("0_", "0\n")
                        for n, _ in plates], fontsize=9)
    ax.set_ylabel("centre deflection per unit load, mm/N")
    ax.set_title("Plate deflection (Fig. 6): icedem (bars), Hertz x finite plate +- tolerance (black)",
                 fontsize=10)
    ax.set_ylim(0, max(s["validation"]["value"] for _, s in plates) * 1.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "plate_deflection.png"), dpi=110)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--icedem", default=os.path.join(ROOT, "build", "dem", "icedem"))
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "validation"))
    ap.add_argument("--replot", action="store_true")
    args = ap.parse_args(argv)
    output_guard.guard([("--out", args.out, output_guard.DIRECTORY)])
    os.makedirs(args.out, exist_ok=True)
    store = os.path.join(args.out, "validation_summaries.json")
    if args.replot:
        with open(store) as f:
            results = [tuple(r) for r in json.load(f)]
    else:
        results = run_all(args.icedem)
        with open(store, "w") as f:
            json.dump(results, f)
    for name, s in results:
        if s["validation"]["case"] == "cantilever":
            plot_cantilever(name, s, args.out)
    plot_plates([(n, s) for n, s in results if s["validation"]["case"] == "plate_deflection"], args.out)
    with open(os.path.join(args.out, "validation.md"), "w") as f:
        f.write("# Validation cases\n\n`scripts/validation_report.py` (every scenarios/validation/*.toml)\n\n")
        f.write("| scenario | metric | value | reference | error | tolerance | passed | extra | wall s |\n")
        f.write("|---|---|---|---|---|---|---|---|---|\n")
        for name, s in results:
            v = s["validation"]
            if v["case"] == "plate_deflection":
                extra = f"E {v['elastic_modulus_MPa']:.1f} MPa"
            elif v["case"] == "wide_cantilever":
                extra = f"{v['failure_mode']} " + ("at the root line" if v["at_root"] else "off the root line")
            else:
                extra = f"{v['failure_mode']} at joint {v['failed_joint']}"
            f.write(f"| {name} | {v['metric']} | {v['value']:.4g} | {v['reference']:.4g} | "
                    f"{100 * v['rel_error']:+.1f} % | {100 * v['tolerance']:.0f} % | {v['passed']} | {extra} | "
                    f"{s['wall_time_s']:.1f} |\n")
    print(f"wrote the plots and validation.md in {args.out}")


if __name__ == "__main__":
    main()
