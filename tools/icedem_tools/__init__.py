"""icedem's Python tools, one package: one runner of the icedem command (runner), one reader of
what a run writes (results), sweeps (spec, execute, aggregate, sweep), the report beside the
seed paper (report, figures, break_pictures, xdmf), the studies, each a sweep file of
sweeps/studies/ (ladder, convergence, stress, with pareto), the validations (validation_report,
fig6_modulus_vs_cfm, edge_load, photo_layout_validation), the flow-model comparison, the input
fuzzer and the photo-to-layout pipeline (photolayout, layout_from_photo). docs/model/architecture.md
lists every module's concern. The commands in scripts/ are thin entry points over it; from a
notebook, put tools/ on sys.path and `from icedem_tools import results`."""
