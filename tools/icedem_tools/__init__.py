"""icedem's Python tools, one package: one runner of the icedem command (runner), one reader of
what a run writes (results), sweeps (spec, execute, aggregate) and the photo-to-layout
pipeline (photolayout). The commands in scripts/ are thin entry points over it; from a
notebook, put tools/ on sys.path and `from icedem_tools import results`."""
