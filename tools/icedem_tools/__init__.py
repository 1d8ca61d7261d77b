"""icedem's Python tools, in rooms by what they do, lowest first; a room imports only from rooms
below it (tests/cli/test_architecture.py checks it, and that no module imports itself back):

- runs: one run: running icedem (runner), reading what it writes (results), sweep files (spec),
  the guard of every file a tool writes (output_guard), pieces, breaks and XDMF views of a run;
- stats: the statistics of a verdict: error against cost (pareto);
- sweeps: sweeps of runs (sweep, execute) and their aggregation over seeds (aggregate);
- reports: a sweep's report beside the seed paper, its tables, figures, pictures and movies;
- studies: the studies and validations, each running its sweep file and writing its page;
- fuzzing: the input fuzzer; photo: floe layouts from photos.

docs/model/architecture.md lists every module's concern. The commands in scripts/ are thin entry
points over it; from a notebook, put tools/ on sys.path and `from icedem_tools.runs import results`."""
