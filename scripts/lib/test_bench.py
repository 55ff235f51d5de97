#!/usr/bin/env python3
"""Tests of scripts/lib/bench.py without GL (CTest: scripts.bench_py): a stand-in for manylights
writes bench --json and render --stats documents whose times follow from the command line and
its environment, so that every figure the harness prints can be checked exactly, and it logs
each call, so that the order of the rounds can be too."""

import contextlib
import io
import json
import os
import stat
import sys
import tempfile
import textwrap
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench  # noqa: E402

# The stand-in: frame = SLOW (environment, default 1) ms per light, with STEP 1.5, 2, ... times
# that in the second, third, ... call; its
# passes `geometry` 10 ms and `lighting` 2 ms per light at pass timing wall or gpu (named as the
# real --json names the clock); light_evaluations = 1000 * lights. render --stats has the
# same figures in render's shape, and load_ms 42.
STAND_IN = textwrap.dedent('''\
    #!/usr/bin/env python3
    import json, os, sys
    args = sys.argv[1:]
    if "--help" in args:  # a build from before --json has none
        print("  --csv TEXT" + ("" if "NO_JSON" in os.environ else "\\n  --json TEXT"))
        sys.exit(0)
    with open(os.environ["STAND_IN_LOG"], "a") as log:
        log.write(os.environ.get("CASE", "?") + "\\n")
    with open(os.environ["STAND_IN_LOG"]) as log:
        calls = len(log.readlines())
    def value(option, default):
        return args[args.index(option) + 1] if option in args else default
    if "--csv" in args:  # such a build's CSV, of one combination
        print("scene on stand-in GL (3.3) via test, driver profile software")
        with open(value("--csv", None), "w") as f:
            f.write("technique,lights,width,height,frames,frame_ms_median,frame_ms_min,frame_ms_max,"
                    "frame_gpu_ms_median,fragment_invocations,passes,light_evaluations,in_range_pairs,"
                    "transparent_light_evaluations,pass_timing,warmup_frames,frame_ms_p95,frame_gpu_ms_p95,pass_gpu_ms\\n"
                    "forward,16,64,36,1,5.000,5.000,5.000,4.000,99,geometry:1.500:50;lighting:3.000:49,80,40,0,"
                    "wall,0,5.000,4.000,geometry:0.100;lighting:0.200\\n")
        sys.exit(0)
    slow = float(os.environ.get("SLOW", "1"))
    if "STEP" in os.environ:  # each call half as slow again as the first
        slow *= 1 + 0.5 * (calls - 1)
    timing = value("--pass-timing", "wall")
    counts = [int(n) for n in value("--lights", "100").split(",")]
    techniques = value("--techniques", value("--technique", "deferred")).split(",")
    def passes(lights):
        result = []
        for name, ms in (("geometry", 10.0), ("lighting", 2.0 * lights)):
            timed = None if timing == "frame" else ms
            result.append({"name": name, "ms": timed, "clock": None if timed is None else timing,
                           "wall_ms": ms if timing == "wall" else None,
                           "gpu_ms": None if timing == "wall" else timed, "fragment_invocations": 7})
        return result
    def frame(lights):
        ms = slow * lights
        return {"median": ms, "p95": ms, "min": ms, "max": ms}
    if args[0] == "bench":
        results = [{"technique": t, "lights": n, "width": 64, "height": 36, "frames": 1, "warmup_frames": 0,
                    "pass_timing": timing, "lighting_stage": "fragment", "frame_ms": frame(n),
                    "frame_gpu_ms": frame(n), "passes": passes(n), "counters": {"cluster_pairs": 3 * n},
                    "work": {"light_evaluations": 1000 * n, "in_range_pairs": 500 * n}}
                   for n in counts for t in techniques]
        document = {"gl_renderer": "stand-in GL", "gl_version": "4.5", "device": "stand-in GL (4.5) via test",
                    "driver_profile": "software", "pass_timing": timing, "results": results}
    else:
        n = counts[0]
        document = {"technique": techniques[0], "lights": n, "width": 64, "height": 36, "device": "stand-in GL",
                    "pass_timing": timing, "frame_ms": frame(n), "frame_gpu_ms": frame(n), "load_ms": 42,
                    "passes": [{k: v for k, v in p.items() if k not in ("ms", "clock")} for p in passes(n)]}
    with open(value("--json", value("--stats", None)), "w") as f:
        json.dump(document, f)
''')


class BenchHarnessTest(unittest.TestCase):
    def setUp(self):
        self.scratch = tempfile.TemporaryDirectory()
        self.binary = os.path.join(self.scratch.name, "manylights")
        with open(self.binary, "w") as f:
            f.write(STAND_IN)
        os.chmod(self.binary, os.stat(self.binary).st_mode | stat.S_IEXEC)
        self.log = os.path.join(self.scratch.name, "calls.log")
        os.environ["STAND_IN_LOG"] = self.log

    def tearDown(self):
        self.scratch.cleanup()

    def measure(self, specs, columns=(), rounds=1):
        cases = [bench.Case(spec, self.binary) for spec in specs]
        measurement = bench.Measurement(cases, [bench.Column(c) for c in columns], rounds)
        out = io.StringIO()
        measurement.run(out)
        return measurement, out.getvalue()

    def calls(self):
        with open(self.log) as f:
            return f.read().split()

    def test_rounds_rotate_the_order_of_the_cases(self):
        self.measure(["a: CASE=a", "b: CASE=b", "c: CASE=c"], rounds=4)
        self.assertEqual(self.calls(), "a b c b c a c a b a b c".split())

    def test_a_case_takes_its_environment_and_binary(self):
        case = bench.Case("slow/x: SLOW=2 ML=/other/manylights --lights 4", self.binary)
        self.assertEqual((case.series, case.point), ("slow", "x"))
        self.assertEqual(case.environment, {"SLOW": "2"})
        self.assertEqual(case.binary, "/other/manylights")
        self.assertEqual(case.command("out.json", 3, 1, ["--driver-profile", "gpu"]),
                         ["/other/manylights", "bench", "--lights", "4", "--json", "out.json", "--frames", "3",
                          "--warmup", "1", "--driver-profile", "gpu"])
        with self.assertRaises(ValueError):
            bench.Case("no label here", self.binary)

    def test_columns_read_each_pass_on_its_clock(self):
        measurement, out = self.measure(["gpu: --lights 10 --pass-timing gpu"],
                                        ["lighting", "both=geometry + lighting", "shading=frame - geometry",
                                         "pairs=counter.cluster_pairs", "share=lighting / frame", "gone=absent*",
                                         "ns a pair=lighting * 1000000 / work.light_evaluations"])
        row = measurement.results[("gpu", ("deferred", 10, "64x36"))][0]
        values = [c.value(row) for c in measurement.columns]
        # lighting 20 ms over 10,000 pairs: 2,000 ns each (a pass's time as a factor of a product).
        self.assertEqual(values, [20.0, 30.0, 0.0, 30.0, 2.0, None, 2000.0])
        self.assertEqual(measurement.column_title(measurement.columns[0]), "lighting (gpu ms)")
        self.assertIn("GL: stand-in GL, 4.5; driver profile software; pass timing gpu", out)

    def test_frame_timing_has_no_pass_times(self):
        measurement, _ = self.measure(["f: --pass-timing frame"], ["lighting"])
        row = next(iter(measurement.results.values()))[0]
        self.assertIsNone(measurement.columns[0].value(row))
        self.assertIn("-", measurement.summary().splitlines()[1])

    def test_summary_has_the_median_and_range_of_the_rounds(self):
        # The frames of the rounds: 100, 150 and 200 ms; the lighting pass 200 ms in each.
        measurement, _ = self.measure(["a: STEP=1 --lights 100"], ["lighting"], rounds=3)
        self.assertEqual(len(measurement.results[("a", ("deferred", 100, "64x36"))]), 3)
        summary = measurement.summary().splitlines()
        self.assertIn("median of 3 rounds", summary[0])
        self.assertIn("lighting (wall ms)", summary[0])
        self.assertRegex(summary[1], r"^a\s+deferred\s+100\s+64x36\s+150\.0 \(100\.0-200\.0\)\s+200\.0$")

    def test_compare_divides_the_first_series_by_the_second(self):
        measurement, _ = self.measure(["slow/p: SLOW=3 --lights 10", "fast/p: --lights 10"], ["lighting"])
        lines = measurement.compare().splitlines()
        self.assertEqual(lines[0], "slow / fast, the ratio of the medians:")
        self.assertRegex(lines[2], r"^p\s+deferred\s+10\s+64x36\s+3\.00\s+1\.00$")

    def test_per_pair_divides_the_change_by_the_change_of_the_pairs(self):
        measurement, _ = self.measure(["a: --lights 10,110 --techniques deferred,tiled"], ["lighting"])
        # lighting: 2 ms per light over 1000 evaluations per light: 2e6 ns / 1000 = 2000 ns.
        lines = measurement.per_pair(measurement.columns[0]).splitlines()
        self.assertEqual(len(lines), 4)
        self.assertRegex(lines[2], r"^a\s+deferred\s+64x36\s+10,000 -> 110,000\s+20\.0 -> 220\.0\s+2000\.00\s+1\.00$")
        in_range = measurement.per_pair(measurement.columns[0], "in_range_pairs").splitlines()
        self.assertIn("4000.00", in_range[2])

    def test_render_cases_give_rows_of_the_same_shape(self):
        measurement, _ = self.measure(["r: render --technique clustered --lights 5"],
                                      ["lighting", "load=stat.load_ms", "rss=peak rss"])
        row = measurement.results[("r", ("clustered", 5, "64x36"))][0]
        self.assertEqual([c.value(row) for c in measurement.columns][:2], [10.0, 42.0])
        self.assertGreater(measurement.columns[2].value(row), 0.0)

    def test_a_failing_command_ends_the_measurement_with_its_message(self):
        with self.assertRaises(SystemExit) as raised:
            self.measure(["bad: ML=/bin/false --lights 1"])
        self.assertIn("failed with exit status 1", str(raised.exception))

    def test_a_build_without_json_is_read_from_its_csv(self):
        os.environ["NO_JSON"] = "1"
        try:
            measurement, out = self.measure(["old: --lights 16"], ["lighting", "work.in_range_pairs"])
        finally:
            del os.environ["NO_JSON"]
        row = measurement.results[("old", ("forward", 16, "64x36"))][0]
        self.assertEqual(row["frame_ms"]["median"], 5.0)
        self.assertEqual([c.value(row) for c in measurement.columns], [3.0, 40.0])
        self.assertEqual(row["passes"][1]["clock"], "wall")
        self.assertIn("GL: stand-in GL (3.3) via test", out)

    def test_the_header_names_the_machine_and_the_commit(self):
        header = bench.machine_header([self.binary])
        self.assertRegex(header, r"machine: .+, \d+ cores, load average [\d.]+ [\d.]+ [\d.]+ at the start")
        self.assertIn("commit: ", header)
        self.assertIn(f"binary: {self.binary}", header)

    def test_machine_and_binary_serve_the_scripts_that_measure_outside_bench(self):
        os.environ["ML"] = self.binary
        try:
            for flag, expected in (("--binary", self.binary + "\n"), ("--machine", f"binary: {self.binary}\n")):
                out = io.StringIO()
                with contextlib.redirect_stdout(out):
                    bench.main([flag])
                self.assertTrue(out.getvalue().endswith(expected), out.getvalue())
            self.assertEqual(self.calls() if os.path.exists(self.log) else [], [])  # nothing was run
        finally:
            del os.environ["ML"]


if __name__ == "__main__":
    unittest.main()
