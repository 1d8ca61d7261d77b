"""Tests of scripts/sweep: expansion, bad files, resume, failure reporting, and a
tiny sweep end to end through GNU parallel with the real icedem.

    /usr/bin/python3 tests/sweep/test_sweep.py ICEDEM WORKDIR
"""
import os
import subprocess
import sys
import tempfile
import textwrap
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools"))
from icedem_tools.sweeps import execute  # noqa: E402
from icedem_tools.runs import spec
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # same_runs, beside this file

ICEDEM = None
WORK = None


def read(path):
    with open(path) as f:
        return f.read()


def write(path, text):
    with open(path, "w") as f:
        f.write(text)


def sweep_file(text):
    f = tempfile.NamedTemporaryFile("w", suffix=".toml", dir=WORK, delete=False)
    f.write(textwrap.dedent(text))
    f.close()
    return f.name


TINY = """
    name = "tiny"
    seeds = [1, 2]
    set = ["time.duration=20", "output.snapshot_interval=0"]
    [[scenario]]
    name = "short"
    file = "scenarios/examples/short_tow.toml"
    [grid]
    "friction.ice_structure" = [0.1, 0.3]
"""


class Expansion(unittest.TestCase):
    def test_scenarios_times_grid_times_seeds(self):
        name, runs = spec.load(sweep_file("""
            seeds = 3
            [[scenario]]
            name = "a"
            file = "scenarios/examples/short_tow.toml"
            [[scenario]]
            name = "b"
            file = "scenarios/examples/short_tow.toml"
            set = ["ice.thickness=0.04"]
            [grid]
            "friction.ice_ice" = [0.3, 0.5, 0.7]
            "friction.ice_structure" = [0.1, 0.2]
        """))
        self.assertEqual(len(runs), 2 * 3 * 2 * 3)
        self.assertEqual(len({r.config for r in runs}), 12)
        self.assertEqual(len({r.path for r in runs}), len(runs))  # every run its own directory
        self.assertEqual(sorted({r.seed for r in runs}), [1, 2, 3])  # a count means 1..N
        b = [r for r in runs if r.scenario == "b"][0]
        # overrides in order: common, scenario, grid, seed (later ones win in icedem)
        self.assertEqual(b.sets, ("ice.thickness=0.04", "friction.ice_ice=0.3", "friction.ice_structure=0.1", "seed=1"))
        self.assertEqual(b.path, os.path.join("b", "friction.ice_ice=0.3,friction.ice_structure=0.1", "seed1"))
        # seed-major: the first 12 runs are every configuration once, at seed 1,
        # so a sweep stopped part-way still covers the whole grid
        self.assertEqual(len({r.config for r in runs[:12]}), 12)
        self.assertEqual({r.seed for r in runs[:12]}, {1})

    def test_no_grid_is_one_configuration(self):
        _, runs = spec.load(sweep_file("""
            seeds = [4, 9]
            [[scenario]]
            name = "a"
            file = "scenarios/examples/short_tow.toml"
        """))
        self.assertEqual([r.path for r in runs], [os.path.join("a", "base", "seed4"), os.path.join("a", "base", "seed9")])

    def test_variants_cross_scenarios_and_a_scenario_adds_its_own(self):
        # the ladder's and the convergence study's shape: named settings of several keys each
        _, runs = spec.load(sweep_file("""
            seeds = 2
            [[scenario]]
            name = "rigid"
            file = "scenarios/examples/short_tow.toml"
            [scenario.variants]
            "substeps 2" = ["time.substeps=2"]
            [[scenario]]
            name = "other"
            file = "scenarios/examples/short_tow.toml"
            [variants]
            "base" = []
            "tol 0.1, cap 40" = ["solver.tolerance=0.1", "solver.iterations=40"]
        """), seeds=1, extra=["time.duration=5"])
        self.assertEqual(sorted((r.scenario, r.variant) for r in runs),
                         [("other", "base"), ("other", "tol 0.1, cap 40"),
                          ("rigid", "base"), ("rigid", "substeps 2"), ("rigid", "tol 0.1, cap 40")])
        tol = next(r for r in runs if r.scenario == "rigid" and r.variant.startswith("tol"))
        # the variant's directory is its name made safe; extra sets come after the file's, then the seed
        self.assertEqual(tol.path, os.path.join("rigid", "tol_0.1_cap_40", "base", "seed1"))
        self.assertEqual(tol.sets, ("solver.tolerance=0.1", "solver.iterations=40", "time.duration=5", "seed=1"))
        self.assertEqual(tol.labels, (("variant", "tol 0.1, cap 40"),))
        # a name used twice, or two names one directory, is an error naming the key
        for text, needle in {'[variants]\n"a" = []\n[[scenario]]\nname="s"\nfile="scenarios/examples/short_tow.toml"\n'
                             '[scenario.variants]\n"a" = ["time.dt=0.01"]': "scenario[0].variants",
                             '[variants]\n"a b" = []\n"a_b" = []\n[[scenario]]\nname="s"\n'
                             'file="scenarios/examples/short_tow.toml"': "distinct as directory names",
                             '[variants]\n"a" = "time.dt=0.01"\n[[scenario]]\nname="s"\n'
                             'file="scenarios/examples/short_tow.toml"': "variants.a"}.items():
            with self.assertRaises(spec.SweepError, msg=text) as cm:
                spec.load(sweep_file(text))
            self.assertIn(needle, str(cm.exception))

    def test_bad_files_name_the_key(self):
        cases = {
            'seeds = 0\n[[scenario]]\nname="a"\nfile="scenarios/examples/short_tow.toml"': "'seeds'",
            'seeds = [1, 1]\n[[scenario]]\nname="a"\nfile="scenarios/examples/short_tow.toml"': "distinct",
            '[[scenario]]\nname="a"\nfile="nope.toml"': "scenario[0].file",
            '[[scenario]]\nname="a"\nfile="scenarios/examples/short_tow.toml"\n[grid]\n"x" = []': "grid.x",
            'sed = [1]\n[[scenario]]\nname="a"\nfile="scenarios/examples/short_tow.toml"': "'sed'",
            'seeds = [1]': "'scenario'",
            '[[scenario]]\nname="a"\nfile="scenarios/examples/short_tow.toml"\nset=["noequals"]': "scenario[0].set",
        }
        for text, needle in cases.items():
            path = sweep_file(text)
            with self.assertRaises(spec.SweepError, msg=text) as cm:
                spec.load(path)
            self.assertIn(path, str(cm.exception))
            self.assertIn(needle, str(cm.exception))


class Aggregation(unittest.TestCase):
    def test_confidence_interval_of_three_values(self):
        from icedem_tools.stats.intervals import mean_ci
        m, half = mean_ci([1.0, 2.0, 3.0])
        # t(0.975, 2) = 4.302653, sample std 1: 4.302653 / sqrt(3)
        self.assertAlmostEqual(m, 2.0, places=12)
        self.assertAlmostEqual(half, 4.302653 / 3 ** 0.5, places=5)
        m1, half1 = mean_ci([5.0])
        self.assertEqual(m1, 5.0)
        self.assertTrue(half1 != half1)  # nan: no interval from one seed

    def test_spectral_peak_of_a_noisy_sine(self):
        from icedem_tools.sweeps import aggregate as agg
        import numpy as np
        rng = np.random.default_rng(1)
        t = np.arange(0, 300, 0.02)
        x = 10 + 5 * np.sin(2 * np.pi * 0.233 * t) + rng.normal(0, 2, t.size)
        # Welch with 60 s segments resolves 1/60 Hz: the peak within one bin of 0.233 Hz
        self.assertLess(abs(agg.spectral_peak(t, x) - 0.233), 1 / 60)

    def test_spectral_peak_ignores_the_slow_drift_of_a_pack(self):
        from icedem_tools.sweeps import aggregate as agg
        import numpy as np
        rng = np.random.default_rng(2)
        t = np.arange(0, 216, 0.02)
        # a 50 s build-up and release three times as strong as the 8.57 s floe passage
        x = 20 + 6 * np.sin(2 * np.pi * t / 50) + 2 * np.sin(2 * np.pi * t / 8.57) + rng.normal(0, 1, t.size)
        f, p = agg.welch_spectrum(t, x)
        self.assertLess(f[np.argmax(p)], agg.MIN_PEAK_HZ)  # the raw maximum is the drift
        self.assertLess(abs(agg.peak_frequency(f, p) - 1 / 8.57), 1 / 60)

    def test_ensemble_spectrum_finds_a_peak_no_single_seed_shows(self):
        from icedem_tools.sweeps import aggregate as agg
        import numpy as np
        rng = np.random.default_rng(3)
        t = np.arange(0, 200, 0.02)
        # weak 0.2 Hz line under strong noise: averaging 20 seeds' spectra cuts the noise
        # power's scatter by sqrt(20), so the line stands out in the mean
        seeds = [agg.welch_spectrum(t, 0.5 * np.sin(2 * np.pi * 0.2 * t + k) + rng.normal(0, 3, t.size))
                 for k in range(20)]
        f, p = agg.ensemble_spectrum(seeds)
        self.assertEqual(len(f), len(seeds[0][0]))
        self.assertLess(abs(agg.peak_frequency(f, p) - 0.2), 1 / 60)
        self.assertTrue(np.allclose(p, np.mean([q for _, q in seeds], axis=0)))

    def test_gumbel_moment_fit_recovers_its_parameters(self):
        from icedem_tools.stats.intervals import gumbel_fit
        import numpy as np
        rng = np.random.default_rng(4)
        x = rng.gumbel(100.0, 15.0, 20000)
        u, beta = gumbel_fit(x)
        # standard errors of moment estimates at n = 20000 are about 0.2 (u) and 0.15 (beta)
        self.assertAlmostEqual(u, 100.0, delta=1.0)
        self.assertAlmostEqual(beta, 15.0, delta=1.0)
        # exact for two values: s = |a - b| / sqrt(2)
        u2, b2 = gumbel_fit([10.0, 20.0])
        self.assertAlmostEqual(b2, 6 ** 0.5 * (10 / 2 ** 0.5) / np.pi)
        self.assertAlmostEqual(u2, 15.0 - 0.5772156649 * b2)
        self.assertTrue(np.isnan(gumbel_fit([5.0])[0]))

    def test_rows_average_over_seeds_and_sum_breaks(self):
        from icedem_tools.sweeps import aggregate as agg
        # a summary counts every mode icedem has, also those that never fired (here shear)
        recs = [{"mean_fx_N": m, "max_fx_N": 10 * m, "peak_interval_s": 4.0, "spectral_peak_hz": 0.25,
                 "breaks_by_mode": {"bending": b, "shear": 0, agg.mode_key("in-plane bending"): 1},
                 "realtime_factor": 5.0,
                 "wall_time_s": 7.0}
                for m, b in ((1.0, 2), (3.0, 1))]
        rows, spectra = agg.aggregate({"s/a=1": ("s", (("a", 1),), recs)})
        self.assertEqual(len(rows), 1)
        self.assertEqual(len(spectra), 1)
        r = rows[0]
        self.assertEqual(r["seeds"], 2)
        self.assertEqual(r["a"], 1)
        self.assertAlmostEqual(r["mean_fx_N"], 2.0)
        self.assertAlmostEqual(r["max_fx_N"], 20.0)
        self.assertAlmostEqual(r["max_fx_cov"], (200 ** 0.5) / 20)  # maxima 10 and 30: s = sqrt(200)
        self.assertAlmostEqual(r["spectral_peak_period_s"], 4.0)
        self.assertEqual(r["breaks_bending"], 3)
        self.assertEqual(r["breaks_in_plane_bending"], 2)
        self.assertEqual(r["breaks_shear"], 0)
        self.assertAlmostEqual(r["run_wall_time_s"], 14.0)

        # a variant is a column of its own, text in results.h5
        rows, spectra = agg.aggregate({"s/dt_0.01/a=1": ("s", (("variant", "dt 0.01"), ("a", 1)), recs)})
        self.assertEqual((rows[0]["variant"], rows[0]["a"], rows[0]["seeds"]), ("dt 0.01", 1, 2))
        path = os.path.join(WORK, "variant_results.h5")
        agg.write_hdf5(rows, path, spectra)
        import h5py
        with h5py.File(path, "r") as h:
            self.assertEqual(h["configurations"]["variant"][0].decode(), "dt 0.01")

    def test_a_cause_cites_its_supplements_ratios(self):
        from icedem_tools.reports import paper_findings
        rows = [{"configuration": "a/base", "mean_fx_N": "10", "max_fx_N": "40"},
                {"configuration": "b/base", "mean_fx_N": "12", "max_fx_N": "60"},
                {"configuration": "c/base", "mean_fx_N": "5", "max_fx_N": "nan"}]
        self.assertEqual(paper_findings.supplement_ratios(rows),
                         " (mean / max against `a`: `b` 1.20 / 1.50, `c` 0.50 / n/a)")
        # a configuration without runs is left out; without the first one there is nothing to cite
        empty = {"configuration": "d/base", "mean_fx_N": "", "max_fx_N": ""}
        self.assertEqual(paper_findings.supplement_ratios(rows + [empty]), paper_findings.supplement_ratios(rows))
        self.assertEqual(paper_findings.supplement_ratios([empty] + rows), "")
        # without supplements every placeholder is left empty, none printed raw
        causes = paper_findings.filled_causes([])
        self.assertEqual(set(causes), set(paper_findings.CAUSES))
        self.assertFalse(any("{" in c or "}" in c for c in causes.values()))


class XdmfExport(unittest.TestCase):
    def test_every_data_item_exists_with_its_dimensions_and_cells_are_consistent(self):
        import xml.etree.ElementTree as ET
        import h5py
        import numpy as np
        out = tempfile.mkdtemp(dir=WORK)
        run = os.path.join(out, "run.h5")
        subprocess.run([ICEDEM, "run", os.path.join(ROOT, "scenarios/examples/short_tow.toml"), "-q", "-o", run,
                        "--set", "time.duration=10", "--set", "output.snapshot_interval=5"], check=True,
                       stdout=subprocess.DEVNULL)
        subprocess.run([os.path.join(ROOT, "scripts", "xdmf_snapshots.py"), run], check=True, stdout=subprocess.DEVNULL)
        root = ET.parse(os.path.join(out, "run.xdmf")).getroot()
        grids = root.findall(".//Grid[@GridType='Uniform']")
        with h5py.File(run, "r") as h:
            self.assertEqual(len(grids), len(h["/snapshots/time"]))
            nb = len(h["/bodies/floe_id"])
            from icedem_tools.runs.results import snapshot_field
            pos0 = snapshot_field(h)[0][0]
            thick = h["/bodies/thickness"][:]
        with h5py.File(os.path.join(out, "run_views.h5"), "r") as v:
            for item in root.iter("DataItem"):
                file, dataset = item.text.split(":")
                self.assertEqual(file, "run_views.h5")
                dims = tuple(int(d) for d in item.get("Dimensions").split())
                self.assertEqual(v[dataset].shape, dims, dataset)
            # Mixed topology: (3, n, ids...) per polygon, two per body, ids inside the points
            topo = v["topology"][:]
            npts = v["points/0"].shape[0]
            i, cells = 0, 0
            while i < len(topo):
                self.assertEqual(topo[i], 3)
                n = topo[i + 1]
                self.assertTrue(np.all(topo[i + 2:i + 2 + n] < npts))
                i += 2 + n
                cells += 1
            self.assertEqual(cells, 2 * nb)
            # body 0's top face is centred h/2 above its centre of mass at t = 0 (floes start level)
            n0 = topo[1]
            top0 = v["points/0"][topo[2:2 + n0]]
            self.assertLess(np.linalg.norm(top0.mean(axis=0) - (pos0[0] + [0, thick[0] / 2, 0])), 1e-9)


class RunnerAndReader(unittest.TestCase):
    def test_a_run_reads_back_with_units_and_named_breaks_and_a_failure_names_its_error(self):
        from icedem_tools.runs import results, runner
        out = os.path.join(WORK, "runner")
        # joints weak enough to break within the run (the golden breakable case, shortened)
        sets = ["time.duration=3", "channel.start_x=3.0", "channel.length=3.6", "channel.width=3.0",
                "ice.concentration=0.6", "structure.start_x=2.2", "structure.speed=0.2",
                "ice.bending_strength=12e3", "stats.window_start_travel=0.1"]
        r = runner.execute(os.path.join(ROOT, "scenarios/paper/large_floes_breakable_015.toml"), out, sets,
                           icedem=ICEDEM)
        self.assertTrue(r.ok, r.log)
        self.assertGreater(r.cpu_time_s, 0)
        run = results.load_run(r.h5)
        self.assertEqual(run["/load/surge"].unit, "N")
        self.assertEqual(run["/load/force"].shape, (r.summary["steps"], 3))
        # the reader's surge is the summary's: the largest value in the window is the summary's max
        t, surge = run["/load/time"], run["/load/surge"]
        window = (t >= r.summary["window_start_s"]) & (t <= r.summary["window_end_s"])
        self.assertAlmostEqual(float(surge[window].max()), r.summary["max_fx_N"], places=9)
        self.assertEqual(len(run.events), r.summary["breaks"])
        self.assertGreater(len(run.events), 0)
        self.assertIn("bending", run.modes.values())
        self.assertTrue(all(name in run.modes.values() for name in run.events["mode_name"]))
        self.assertEqual(run.meta["status"], "complete")
        # a bad key: exit 2, the error line names it, no summary
        bad = runner.execute(os.path.join(ROOT, "scenarios/examples/short_tow.toml"), os.path.join(out, "bad"),
                             ["ice.thicknes=0.03"], icedem=ICEDEM)
        self.assertFalse(bad.ok)
        self.assertEqual(bad.returncode, 2)
        self.assertIn("ice.thicknes", bad.error)
        self.assertIsNone(bad.summary)


class Execution(unittest.TestCase):
    def test_kept_records_finish_a_sweep_on_a_machine_without_its_runs(self):
        # a sweep that keeps records: after aggregation every run has one; with the run
        # directories gone (another machine), the runs still count as finished and the
        # aggregation from the records alone gives the same table
        records = tempfile.mkdtemp(dir=WORK)
        path = sweep_file(TINY.replace('seeds = [1, 2]', f'seeds = [1, 2]\n    records = "{records}"'))
        out = tempfile.mkdtemp(dir=WORK)
        _, runs = spec.load(path)
        execute.run_parallel(runs, out, ICEDEM)

        def aggregate(o):
            p = subprocess.run([os.path.join(ROOT, "scripts", "sweep"), "aggregate", path, "--out", o],
                               capture_output=True, text=True)
            self.assertEqual(p.returncode, 0, p.stdout + p.stderr)
            return read(os.path.join(o, "results.csv"))
        first = aggregate(out)
        for r in runs:
            self.assertTrue(os.path.isfile(r.record_file), r.record_file)
        import json
        rec = json.loads(read(runs[0].record_file))
        self.assertEqual(set(rec), {"summary", "spectrum", "fracture_events", "window", "pieces"})
        # the tiny sweep's floes are rigid: nothing broke off
        self.assertEqual(rec["pieces"], {"pieces": 0})
        # the window's 99th percentile: within the run's surge load, at most its max
        self.assertLessEqual(rec["window"]["p99_fx_N"], rec["summary"]["max_fx_N"])
        self.assertGreater(len(rec["spectrum"]["frequency_hz"]), 10)
        self.assertLessEqual(max(rec["spectrum"]["frequency_hz"]), 2.0)
        elsewhere = os.path.join(tempfile.mkdtemp(dir=WORK), "new")  # the same sweep, no directory at all
        self.assertEqual([execute.status(r, elsewhere).state for r in runs], ["done"] * 4)
        self.assertEqual(execute.run_parallel(runs, elsewhere, ICEDEM)[0].state, "done")
        self.assertFalse(os.path.exists(os.path.join(elsewhere, runs[0].path)))  # nothing was rerun
        self.assertEqual(aggregate(elsewhere), first)
        # every record names the build that made it; one build: aggregation notes nothing, two
        # builds in one configuration: it says so, with the runs of each
        build = rec["summary"]["build"]
        self.assertRegex(build["commit"], "^([0-9a-f]{40}|unknown)$")
        quiet = subprocess.run([os.path.join(ROOT, "scripts", "sweep"), "aggregate", path, "--out", out],
                               capture_output=True, text=True)
        self.assertNotIn("builds (", quiet.stdout)
        other = json.loads(read(runs[1].record_file))
        other["summary"]["build"] = dict(build, commit="0" * 40, modified=True)
        with open(runs[1].record_file, "w") as f:
            json.dump(other, f)
        mixed = subprocess.run([os.path.join(ROOT, "scripts", "sweep"), "aggregate", path, "--out", elsewhere],
                               capture_output=True, text=True)
        self.assertEqual(mixed.returncode, 0, mixed.stdout + mixed.stderr)
        self.assertIn(f"note: {runs[1].config}: its runs were made by 2 builds (000000000000 (modified): 1, ",
                      mixed.stdout)
        # a record of another run than its directory holds (a figure's rerun by another build) is
        # never replaced, even one made before records kept the window (which is otherwise remade
        # from the directory): it stays byte for byte, and a warning names the directory
        old = json.loads(read(runs[0].record_file))
        del old["window"]
        max_fx = old["summary"]["max_fx_N"]
        old["summary"]["max_fx_N"] = max_fx + 1.0
        with open(runs[0].record_file, "w") as f:
            json.dump(old, f)
        os.utime(runs[0].record_file, (1, 1))  # older than the run's summary
        before = read(runs[0].record_file)
        kept = subprocess.run([os.path.join(ROOT, "scripts", "sweep"), "aggregate", path, "--out", out],
                              capture_output=True, text=True)
        self.assertEqual(kept.returncode, 0, kept.stdout + kept.stderr)
        self.assertEqual(read(runs[0].record_file), before)
        self.assertIn(f"{os.path.join(out, runs[0].path)} holds another run than its record", kept.stderr)
        # the same run: the old record is made again from the directory, with its window
        old["summary"]["max_fx_N"] = max_fx
        with open(runs[0].record_file, "w") as f:
            json.dump(old, f)
        os.utime(runs[0].record_file, (1, 1))
        remade = subprocess.run([os.path.join(ROOT, "scripts", "sweep"), "aggregate", path, "--out", out],
                                capture_output=True, text=True)
        self.assertNotIn("holds another run", remade.stderr)
        self.assertIn("window", json.loads(read(runs[0].record_file)))

    def test_tiny_sweep_end_to_end_resume_and_failures(self):
        path = sweep_file(TINY)
        out = tempfile.mkdtemp(dir=WORK)
        _, runs = spec.load(path)
        statuses = execute.run_parallel(runs, out, ICEDEM)
        self.assertEqual([s.state for s in statuses], ["done"] * 4, [s.error for s in statuses])
        for r in runs:
            self.assertTrue(os.path.isfile(os.path.join(out, r.path, "run.h5")))
        # resume: nothing is rerun (summaries untouched)
        stamps = {r.path: os.stat(os.path.join(out, r.path, "summary.json")).st_mtime_ns for r in runs}
        execute.run_parallel(runs, out, ICEDEM)
        for r in runs:
            self.assertEqual(os.stat(os.path.join(out, r.path, "summary.json")).st_mtime_ns, stamps[r.path])
        # a killed run (no exit code) is pending and is run again
        os.remove(os.path.join(out, runs[0].path, "exit_code"))
        self.assertEqual(execute.status(runs[0], out).state, "pending")
        execute.run_parallel(runs, out, ICEDEM)
        self.assertEqual(execute.status(runs[0], out).state, "done")

        # aggregation: one row per configuration, both seeds in it, in CSV and HDF5
        p = subprocess.run([os.path.join(ROOT, "scripts", "sweep"), "aggregate", path, "--out", out],
                           capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stdout + p.stderr)
        import csv
        import h5py
        with open(os.path.join(out, "results.csv")) as f:
            rows = list(csv.DictReader(f))
        self.assertEqual(len(rows), 2)
        self.assertEqual({r["seeds"] for r in rows}, {"2"})
        self.assertTrue(all(float(r["mean_fx_N"]) > 0 for r in rows))
        with h5py.File(os.path.join(out, "results.h5"), "r") as h:
            self.assertEqual(h["configurations"].shape, (2,))
        # figures from the aggregated table and the runs (no snapshots here: no top view)
        p = subprocess.run([os.path.join(ROOT, "scripts", "sweep_figures.py"), path, "--out", out],
                           capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stdout + p.stderr)
        for kind in ("loads_vs_fis", "history"):
            self.assertTrue(os.path.getsize(os.path.join(out, "figures", f"{kind}_short.png")) > 1000)

        # a failing configuration is reported with icedem's error, the others still run
        bad = sweep_file(TINY.replace("[0.1, 0.3]", "[0.1, 7.0]"))
        out2 = tempfile.mkdtemp(dir=WORK)
        _, runs2 = spec.load(bad)
        statuses = execute.run_parallel(runs2, out2, ICEDEM)
        failed = [s for s in statuses if s.state == "failed"]
        self.assertEqual(len(failed), 2)
        self.assertEqual(sum(s.state == "done" for s in statuses), 2)
        for s in failed:
            self.assertIn("friction.ice_structure", s.error)
            self.assertIn("exit code 2", s.error)
        # the command line reports them and exits 1
        p = subprocess.run([os.path.join(ROOT, "scripts", "sweep"), "status", bad, "--out", out2],
                           capture_output=True, text=True)
        self.assertEqual(p.returncode, 1)
        self.assertIn("2 failed", p.stdout)
        self.assertEqual(p.stdout.count("FAILED"), 2)

    def test_a_sweep_killed_mid_run_resumes_its_runs_from_their_checkpoints(self):
        # the tiny sweep with a checkpoint every 5 s, once whole and once killed (SIGKILL to the
        # whole sweep, as a lost node) when two runs have checkpointed: rerun, the killed runs
        # resume from their checkpoints and every run ends as in the whole sweep, bit for bit
        import signal
        import time
        from same_runs import datasets
        text = TINY.replace('"output.snapshot_interval=0"]', '"output.snapshot_interval=0", "output.checkpoint_interval=5"]')
        path = sweep_file(text)
        _, runs = spec.load(path)
        whole, killed = tempfile.mkdtemp(dir=WORK), tempfile.mkdtemp(dir=WORK)
        self.assertEqual([s.state for s in execute.run_parallel(runs, whole, ICEDEM, jobs=2)], ["done"] * 4)
        proc = subprocess.Popen([os.path.join(ROOT, "scripts", "sweep"), "run", path, "--out", killed, "--jobs", "2",
                                 "--icedem", ICEDEM], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                start_new_session=True)
        checkpoints = lambda: [r for r in runs if os.path.exists(os.path.join(killed, r.path, "run.h5.checkpoint"))]
        deadline = time.time() + 120
        while len(checkpoints()) < 2 and proc.poll() is None and time.time() < deadline:
            time.sleep(0.01)
        # every process of the sweep's session (GNU parallel puts its jobs in groups of their own)
        subprocess.run(["pkill", "-KILL", "-s", str(proc.pid)], check=False)
        proc.wait()
        while subprocess.run(["pgrep", "-s", str(proc.pid)], stdout=subprocess.DEVNULL).returncode == 0:
            time.sleep(0.01)
        resumable = checkpoints()
        self.assertGreaterEqual(len(resumable), 2, "two runs should have been killed after a checkpoint")
        self.assertTrue(all(execute.status(r, killed).state == "pending" for r in resumable))
        self.assertEqual([s.state for s in execute.run_parallel(runs, killed, ICEDEM, jobs=2)], ["done"] * 4)
        for r in resumable:
            self.assertIn("resuming", read(os.path.join(killed, r.path, "log.txt")))
        for r in runs:
            self.assertEqual(datasets(os.path.join(killed, r.path, "run.h5")),
                             datasets(os.path.join(whole, r.path, "run.h5")), r.path)

    def test_report_sets_the_sweep_beside_the_paper(self):
        # the paper's scenario names on the short channel: small and large rigid floes
        path = sweep_file("""
            name = "mini_paper"
            seeds = [1]
            set = ["time.duration=25", "output.snapshot_interval=0"]
            [[scenario]]
            name = "small_rigid"
            file = "scenarios/examples/short_tow.toml"
            [[scenario]]
            name = "large_rigid"
            file = "scenarios/examples/short_tow.toml"
            set = ["ice.floe_size=0.6", "ice.concentration=0.7"]
            [grid]
            "friction.ice_ice" = [0.5]
            "friction.ice_structure" = [0.1, 0.2]
        """)
        out = tempfile.mkdtemp(dir=WORK)
        docs = os.path.join(out, "docs")  # report and figures elsewhere, as scripts/reproduce_paper does
        for cmd in (["sweep", "run", path, "--icedem", ICEDEM], ["sweep", "aggregate", path],
                    ["sweep_figures.py", path, "--figures", os.path.join(docs, "figures")],
                    ["report", path, "--report", os.path.join(docs, "report.md"),
                     "--figures", os.path.join(docs, "figures")]):
            p = subprocess.run([os.path.join(ROOT, "scripts", cmd[0])] + cmd[1:] + ["--out", out],
                               capture_output=True, text=True)
            self.assertEqual(p.returncode, 0, cmd[0] + ": " + p.stdout + p.stderr)
        text = read(os.path.join(docs, "report.md"))
        import csv
        with open(os.path.join(out, "results.csv")) as f:
            rows = {(r["scenario"], r["friction.ice_structure"]): r for r in csv.DictReader(f)}
        # the ratio row is large / small mean at f_is 0.2, to the 2 decimals it prints
        ratio = [l for l in text.splitlines() if l.startswith("| ratio larger (rigid) / smaller floes, mean load")][0]
        expected = float(rows[("large_rigid", "0.2")]["mean_fx_N"]) / float(rows[("small_rigid", "0.2")]["mean_fx_N"])
        self.assertEqual(ratio.split("|")[3].strip(), f"{expected:.2f}")
        # every row judged "no" is listed again under the disagreements, with its numbers
        # (each such row links to that section)
        table = [l for l in text.splitlines()
                 if l.startswith("| ") and l.endswith("| **no** ([why](#where-icedem-disagrees-with-the-paper)) |")]
        section = text.split("## Where icedem disagrees with the paper")[1].split("## Every configuration")[0]
        # the short tow's larger floes stay far below the paper's 300 N: judged "no" and listed
        self.assertLess(float(rows[("large_rigid", "0.2")]["max_fx_N"]), 300)
        self.assertTrue(any(l.startswith("| larger rigid floes: max load") for l in table))
        for l in table:
            self.assertIn(f"**{l.split('|')[1].strip()}**", section)
        self.assertIn("![loads_vs_fis_small_rigid.png](figures/loads_vs_fis_small_rigid.png)", text)
        self.assertEqual(text.count("| small_rigid/"), 2)
        self.assertIn("4 of 4 runs finished", text)
        self.assertIn("GNU parallel's job log holds 4 jobs (stopped and rerun ones included)", text)
        # a later partial run (two jobs) replaces the job log: the report does not take it for the grid's
        log = os.path.join(out, "joblog.txt")
        lines = read(log).splitlines(keepends=True)
        write(log, "".join(lines[:2]))
        p = subprocess.run([os.path.join(ROOT, "scripts", "report"), path, "--out", out, "--report",
                            os.path.join(out, "partial_log.md")], capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stdout + p.stderr)
        self.assertIn("job log holds 2 jobs, fewer than the 4 runs finished", read(os.path.join(out, "partial_log.md")))
        write(log, "".join(lines))
        # against an earlier build: the sweep against itself changes by a ratio of 1, within scatter
        p = subprocess.run([os.path.join(ROOT, "scripts", "report"), path, "--out", out, "--report",
                            os.path.join(out, "before.md"), "--before", out, "--before-note", "itself"],
                           capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stdout + p.stderr)
        section = read(os.path.join(out, "before.md")).split("## Against an earlier build")[1].split("## Every")[0]
        rows_before = [l for l in section.splitlines() if l.startswith("| small_rigid/") or l.startswith("| large_rigid/")]
        self.assertEqual(len(rows_before), 4)
        for l in rows_before:
            cells = [c.strip() for c in l.split("|")]
            self.assertEqual((cells[4], cells[5], cells[7], cells[8]), ("1.00", "yes", "1.00", "yes"), l)
        # a failed run is listed with its error, not silently dropped
        _, runs = spec.load(path)
        d = os.path.join(out, runs[0].path)
        write(os.path.join(d, "exit_code"), "3\n")
        write(os.path.join(d, "log.txt"), "error: numerical blow-up at step 7\n")
        p = subprocess.run([os.path.join(ROOT, "scripts", "report"), path, "--out", out, "--report",
                            os.path.join(out, "failed.md")], capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stdout + p.stderr)
        text = read(os.path.join(out, "failed.md"))
        self.assertIn("3 of 4 runs finished", text)
        self.assertIn(f"- `{runs[0].path}`: exit code 3: error: numerical blow-up at step 7", text)

    def test_slurm_script_lists_only_unfinished_runs(self):
        path = sweep_file(TINY)
        out = tempfile.mkdtemp(dir=WORK)
        _, runs = spec.load(path)
        # pretend the first run finished
        d = os.path.join(out, runs[0].path)
        os.makedirs(d)
        write(os.path.join(d, "summary.json"), "{}")
        write(os.path.join(d, "exit_code"), "0\n")
        script, n = execute.slurm_script(runs, out, ICEDEM, "tiny")
        self.assertEqual(n, 3)
        text = read(script)
        self.assertIn("#SBATCH --array=0-2", text)
        jobs = read(os.path.join(out, "slurm", "jobs.txt")).splitlines()
        self.assertEqual(len(jobs), 3)
        self.assertFalse(any(runs[0].path in j for j in jobs))


if __name__ == "__main__":
    ICEDEM, WORK = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    os.makedirs(WORK, exist_ok=True)
    unittest.main(argv=sys.argv[:1], verbosity=2)
