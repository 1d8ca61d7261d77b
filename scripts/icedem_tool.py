#!/usr/bin/python3
"""The one entry point of the project's Python commands (tools/icedem_tools/).

Every command of scripts/ below is a link to this file; the name it is called by picks the
module whose main() runs. `scripts/icedem_tool.py` alone lists them; `scripts/icedem_tool.py
COMMAND ARGS...` runs one by name. A new command is a row here and a link:
`ln -s icedem_tool.py scripts/NAME`.
"""
import importlib
import os
import sys

# command (as scripts/ names it) -> (room.module of tools/icedem_tools, what it does)
COMMANDS = {
    "sweep": ("sweeps.sweep", "parameter sweeps of icedem runs: scenarios x variants x grid x seeds"),
    "report": ("reports.report", "a sweep's report beside the seed paper"),
    "sweep_figures.py": ("reports.figures", "a sweep's figures (and XDMF views for ParaView)"),
    "full_runs": ("studies.full_runs", "the contact solve judged on the paper's full runs"),
    "convergence": ("studies.convergence", "convergence of the contact solve, error against cost"),
    "convergence_check": ("studies.convergence_check", "whether a <model>+<numerics> sweep's findings move with its numerics"),
    "level_ice_report": ("studies.level_ice_report", "a level-ice sweep's loads against ISO 19906 and Ralston, and where it broke"),
    "ladder": ("studies.ladder", "run time against error, a ladder of solver settings"),
    "budget": ("studies.budget", "the model-error budget against the tank: what each factor does to the loads"),
    "estimator_coverage": ("studies.estimator_coverage",
                           "which interval the verdicts use: each estimator's coverage on the budget's records"),
    "flow_models": ("studies.flow_models", "the flow models over seeds against the analytic flow, from the records"),
    "mooring_stiffness": ("studies.mooring_stiffness",
                          "the moored cone's stiffness study against the fixed cone, from the records"),
    "tank_maxima": ("studies.tank_maxima", "the tank's largest load against the distribution of the runs' maxima"),
    "stress": ("studies.stress", "the numerical stability stress suite"),
    "fuzz": ("fuzzing.fuzz", "fuzz icedem's input handling with mutated scenario and layout files"),
    "layout_from_photo": ("photo.layout_from_photo", "a floe layout file from a top-view photo of the floes"),
    "photo_layout_validation.py": ("photo.photo_layout_validation",
                                   "validation of scripts/layout_from_photo on synthetic photos of known layouts"),
    "validation_report.py": ("studies.validation_report", "run the validation scenarios (scenarios/validation/) and plot them"),
    "fig6_modulus_vs_cfm.py": ("studies.fig6_modulus_vs_cfm",
                               "the seed paper's Figure 6 for this solver: elastic modulus against the joints' CFM"),
    "edge_load.py": ("studies.edge_load", "the vertical edge load that breaks a square floe floating on water, in bending"),
    "break_pictures.py": ("reports.break_pictures", "pictures of breaks like the seed paper's Fig. 18"),
    "piece_sizes": ("runs.pieces", "the sizes of the pieces a run's breakable ice broke into"),
    "fracture_events.py": ("runs.fracture_events", "the joint breaks of one run: count by mode, and where they happened"),
    "compare_flow_models.py": ("studies.compare_flow_models",
                               "the flow models compared on one scenario: still water, analytic and OpenFOAM"),
    "xdmf_snapshots.py": ("runs.xdmf", "a run's snapshots as an XDMF view for ParaView"),
    "movie": ("reports.movie", "a movie of a run: the floes from above and the side, the cracks, the load beside them"),
}


def main():
    here = os.path.dirname(os.path.abspath(__file__))  # scripts/, also when called through a link
    sys.path.insert(0, os.path.join(os.path.dirname(here), "tools"))
    name = os.path.basename(sys.argv[0])
    if name == "icedem_tool.py":
        if len(sys.argv) < 2 or sys.argv[1] not in COMMANDS:
            print(__doc__.strip() + "\n\ncommands:")
            for command, (_, what) in COMMANDS.items():
                print(f"  scripts/{command:<28} {what}")
            return 0 if len(sys.argv) < 2 else 2
        name = sys.argv.pop(1)
        sys.argv[0] = os.path.join(here, name)
    if name not in COMMANDS:
        print(f"{name}: not a command of scripts/icedem_tool.py (run it alone for the list)", file=sys.stderr)
        return 2
    module = importlib.import_module(f"icedem_tools.{COMMANDS[name][0]}")
    from icedem_tools.runs import output_guard  # noqa: E402 (on the path set above)
    try:
        return module.main()
    except output_guard.Refused as e:  # before any work: nothing written
        print(f"{name}: error: {e}", file=sys.stderr)
        return 2
    except output_guard.WriteFailed as e:
        print(f"{name}: error: {e}", file=sys.stderr)
        return 5


if __name__ == "__main__":
    sys.exit(main())
