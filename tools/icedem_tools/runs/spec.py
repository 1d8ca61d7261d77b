"""A sweep description (TOML) and its expansion into runs.

    name = "friction"
    seeds = [1, 2, 3]              # or a count: seeds = 10 means 1..10
    set = ["time.duration=100"]    # overrides for every run (optional)
    records = "docs/study/records"  # keep every finished run's record here (optional)

    [[scenario]]
    name = "small_rigid"
    file = "scenarios/paper/small_floes.toml"   # relative to the repository root
    set = ["output.snapshot_interval=0"]       # overrides for this scenario (optional)

    [grid]                          # every combination of these values
    "friction.ice_ice" = [0.3, 0.5, 0.7]
    "friction.ice_structure" = [0.1, 0.2, 0.3]

    [variants]                      # named sets of overrides, for every scenario (optional)
    "dt 0.01" = ["time.dt=0.01"]
    "converged" = ["solver.tolerance=0.001", "solver.iterations=160"]

    [study]                         # free data for the study script that reports on the
    mean_tolerance = 0.05           # sweep (scripts/ladder, scripts/convergence); not read here

A [[scenario]] may have variants of its own ([scenario.variants] after it), run
besides the common ones; a sweep with variants runs only them (list "base" = []
to run the scenario as it is too). Variants are for settings that change
several keys together, where a grid would cross values that do not belong
together: the rungs of a ladder, the candidate settings of a convergence study.

Runs = scenarios x variants x grid combinations x seeds. A configuration is a
scenario with one variant and one grid combination; its seeds are its runs.
Each run has a stable, readable directory:
<scenario>/[<variant>/]<key=value,...>/seed<N>, so a rerun finds what an
earlier one finished whatever the order of the list. The list is seed-major
(all configurations for the first seed, then the second, ...).

A run's record (aggregate.py) is what the aggregation and the report
read: its summary, its load spectrum and its breaks. With `records` set, each
record is also kept as <records>/<run directory>.json, small enough to commit:
a sweep resumed on another machine counts those runs as finished, so a grid
of many CPU hours can be run in parts and its report rebuilt from the records.
"""
import itertools
import os
import re
import tomllib
from dataclasses import dataclass, field

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))  # tools/icedem_tools/runs/


class SweepError(Exception):
    """A bad sweep description: the message names the file and the key."""


@dataclass(frozen=True)
class Run:
    scenario: str              # scenario name in the sweep
    scenario_file: str         # absolute path
    grid: tuple                # ((key, value), ...) of this configuration, in the sweep's key order
    seed: int
    sets: tuple = field(default=())  # every --set, variant, grid and seed included, in order
    records: str = ""          # absolute directory of the sweep's kept records, "" if none
    variant: str = ""          # the variant's name, "" in a sweep without variants

    @property
    def config(self):
        """Directory of the configuration (all seeds)."""
        label = ",".join(f"{k}={fmt(v)}" for k, v in self.grid) or "base"
        if self.variant:
            return os.path.join(self.scenario, slug(self.variant), label)
        return os.path.join(self.scenario, label)

    @property
    def labels(self):
        """What tells this configuration from the sweep's others: the variant, then the grid."""
        return ((("variant", self.variant),) if self.variant else ()) + self.grid

    @property
    def path(self):
        """Directory of this run, relative to the sweep's output directory."""
        return os.path.join(self.config, f"seed{self.seed}")

    @property
    def record_file(self):
        """The kept record of this run ("" when the sweep keeps none)."""
        return os.path.join(self.records, self.path + ".json") if self.records else ""


def slug(text):
    """A variant's name as a directory name: letters, digits, '.', '-' and '+'; every run of
    other characters one '_'."""
    return re.sub(r"[^0-9A-Za-z.+-]+", "_", text).strip("_")


def fmt(value):
    """A grid value as TOML would write it in --set (and in directory names)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return value
    return repr(value)


def _fail(path, key, expected, got=None):
    what = f"{path}: key '{key}': expected {expected}"
    if got is not None:
        what += f", got {got!r}"
    raise SweepError(what)


def _string_list(path, key, value):
    if not isinstance(value, list) or not all(isinstance(s, str) and "=" in s for s in value):
        _fail(path, key, 'a list of "key=value" strings', value)
    return list(value)


def _variants(path, key, table):
    if not isinstance(table, dict):
        _fail(path, key, 'a table of name = ["key=value", ...]', table)
    for name, sets in table.items():
        if not slug(name):
            _fail(path, f"{key}.{name}", "a name with a letter or digit")
        _string_list(path, f"{key}.{name}", sets)
    return {name: list(sets) for name, sets in table.items()}


def load(path, seeds=None, extra=()):
    """Parse a sweep file; returns (name, runs). Raises SweepError naming file and key.
    `seeds` (a count) replaces the file's seeds; `extra` sets are added to every run's after
    the file's own, so they win (a study run shorter, or with a physics variant)."""
    try:
        with open(path, "rb") as f:
            doc = tomllib.load(f)
    except FileNotFoundError:
        raise SweepError(f"{path}: no such sweep file")
    except tomllib.TOMLDecodeError as e:
        raise SweepError(f"{path}: {e}")
    known = {"name", "seeds", "set", "scenario", "grid", "records", "variants", "study"}
    for key in doc:
        if key not in known:
            _fail(path, key, "one of " + ", ".join(sorted(known)) + " (unknown key)")
    name = doc.get("name", os.path.splitext(os.path.basename(path))[0])
    if not isinstance(name, str) or not name:
        _fail(path, "name", "a non-empty string", name)

    seeds = doc.get("seeds", [1]) if seeds is None else seeds
    if isinstance(seeds, int) and not isinstance(seeds, bool):
        if seeds < 1:
            _fail(path, "seeds", "a count of at least 1 or a list of seeds", seeds)
        seeds = list(range(1, seeds + 1))
    if not isinstance(seeds, list) or not seeds or not all(
            isinstance(s, int) and not isinstance(s, bool) and s >= 0 for s in seeds):
        _fail(path, "seeds", "a count or a non-empty list of non-negative integers", seeds)
    if len(set(seeds)) != len(seeds):
        _fail(path, "seeds", "distinct seeds", seeds)
    common = _string_list(path, "set", doc.get("set", []))
    extra = _string_list(path, "extra sets", list(extra))
    variants = _variants(path, "variants", doc.get("variants", {}))
    if not isinstance(doc.get("study", {}), dict):
        _fail(path, "study", "a table", doc.get("study"))
    records = doc.get("records", "")
    if not isinstance(records, str):
        _fail(path, "records", "a directory path relative to the repository", records)
    if records and not os.path.isabs(records):
        records = os.path.join(ROOT, records)

    scenarios = doc.get("scenario")
    if not isinstance(scenarios, list) or not scenarios:
        _fail(path, "scenario", "at least one [[scenario]] table with name and file")
    names = set()
    parsed = []
    for i, sc in enumerate(scenarios):
        where = f"scenario[{i}]"
        if not isinstance(sc, dict):
            _fail(path, where, "a table")
        for key in sc:
            if key not in ("name", "file", "set", "variants"):
                _fail(path, f"{where}.{key}", "one of name, file, set, variants (unknown key)")
        sc_name = sc.get("name")
        if not isinstance(sc_name, str) or not sc_name or "/" in sc_name:
            _fail(path, f"{where}.name", "a non-empty name without '/'", sc_name)
        if sc_name in names:
            _fail(path, f"{where}.name", "a name not used by another scenario", sc_name)
        names.add(sc_name)
        file = sc.get("file")
        if not isinstance(file, str):
            _fail(path, f"{where}.file", "a scenario file path", file)
        full = file if os.path.isabs(file) else os.path.join(ROOT, file)
        if not os.path.isfile(full):
            _fail(path, f"{where}.file", "an existing scenario file", file)
        own = _variants(path, f"{where}.variants", sc.get("variants", {}))
        clash = set(own) & set(variants)
        if clash:
            _fail(path, f"{where}.variants", "names other than the common variants'", sorted(clash))
        sc_variants = {**variants, **own}
        slugs = [slug(v) for v in sc_variants]
        if len(set(slugs)) != len(slugs):
            _fail(path, f"{where}.variants", "names that stay distinct as directory names", list(sc_variants))
        parsed.append((sc_name, full, _string_list(path, f"{where}.set", sc.get("set", [])),
                       sc_variants or {"": []}))

    grid = doc.get("grid", {})
    if not isinstance(grid, dict):
        _fail(path, "grid", "a table of key = [values]")
    for key, values in grid.items():
        if not isinstance(values, list) or not values:
            _fail(path, f"grid.{key}", "a non-empty list of values", values)
        if len(set(map(fmt, values))) != len(values):
            _fail(path, f"grid.{key}", "distinct values", values)

    # Seed-major order: every configuration's first seed runs before any
    # configuration's second, so a sweep stopped part-way (a long grid is many
    # CPU hours) leaves a balanced ensemble that aggregates over fewer seeds.
    keys = list(grid)
    combos = [tuple(zip(keys, c)) for c in itertools.product(*(grid[k] for k in keys))]
    runs = []
    for seed in seeds:
        for sc_name, full, sc_sets, sc_variants in parsed:
            for variant, v_sets in sc_variants.items():
                for g in combos:
                    sets = tuple(common + sc_sets + v_sets + [f"{k}={fmt(v)}" for k, v in g] + extra
                                 + [f"seed={seed}"])
                    runs.append(Run(sc_name, full, g, seed, sets, records, variant))
    return name, runs


def key_default(key):
    """A scenario key's default as icedem declares it (docs/user/scenario_keys.md, made by `icedem keys`)."""
    for line in open(os.path.join(ROOT, "docs", "user", "scenario_keys.md"), encoding="utf-8"):
        if line.startswith(f"| `{key}` |"):
            return tomllib.loads("v = " + line.split("|")[3].strip().strip("`"))["v"]
    raise KeyError(key)


def run_value(run, key):
    """A scenario key's value in a run: its last --set of it (the sweep's, its scenario's, its variant's and its
    grid's are all among run.sets), else its scenario file's, else icedem's default. A --set value that is not TOML
    (a bare word) is taken as the text it is. OSError if the scenario file cannot be read."""
    for s in reversed(run.sets):
        k, _, value = s.partition("=")
        if k.strip() == key:
            try:
                return tomllib.loads("v = " + value)["v"]
            except tomllib.TOMLDecodeError:
                return value.strip()
    with open(run.scenario_file, "rb") as f:
        table = tomllib.load(f)
    *sections, name = key.split(".")
    for section in sections:
        table = table.get(section, {})
    return table[name] if name in table else key_default(key)


def bullet_step(run):
    """The Bullet step a run takes, time.dt / time.substeps, s: from its --set values (the last wins),
    else its scenario file, else icedem's defaults. Read from what the sweep declares, since a run's
    record keeps only its outer step."""
    return run_value(run, "time.dt") / run_value(run, "time.substeps")
