#!/usr/bin/env python3
"""Tests of write_test_groups.py (CTest: scripts.write_test_groups_py).

The grouping on a listing written here by hand, and, for each test program and filter given as
PROGRAM[=FILTER] arguments, that the CTest file the build wrote from it (GROUPS_FILE) runs every
test the program lists exactly once: no test is lost by running them a few to a process.

    test_write_test_groups.py [GROUPS_FILE PROGRAM[=FILTER]]...
"""
import collections
import os
import re
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import write_test_groups as groups  # noqa: E402

# As GoogleTest 1.12 prints it: plain suites, a value-parameterised test with comments, a typed
# suite.
LISTING = """Cli.
  BadSceneIsOneLine
  MissingFileIsOneLine
Techniques/Analytic.
  PointLight/forward  # GetParam() = "forward"
  PointLight/deferred  # GetParam() = "deferred"
  SpotLight/forward  # GetParam() = "forward"
Sizes/Typed/0.  # TypeParam = int
  Holds
"""


class Grouping(unittest.TestCase):
    def test_listing_gives_full_names_in_order_without_comments(self):
        self.assertEqual(groups.parse_listing(LISTING), [
            "Cli.BadSceneIsOneLine", "Cli.MissingFileIsOneLine", "Techniques/Analytic.PointLight/forward",
            "Techniques/Analytic.PointLight/deferred", "Techniques/Analytic.SpotLight/forward", "Sizes/Typed/0.Holds"
        ])

    def test_instances_of_a_parameterised_test_share_a_group_and_a_plain_suite_its_own(self):
        made = groups.groups(groups.parse_listing(LISTING), 8)
        self.assertEqual(made, [
            ("Cli", ["Cli.BadSceneIsOneLine", "Cli.MissingFileIsOneLine"]),
            ("Techniques/Analytic.PointLight",
             ["Techniques/Analytic.PointLight/forward", "Techniques/Analytic.PointLight/deferred"]),
            ("Techniques/Analytic.SpotLight", ["Techniques/Analytic.SpotLight/forward"]),
            ("Sizes/Typed/0", ["Sizes/Typed/0.Holds"]),
        ])

    def test_a_group_larger_than_the_size_is_cut_into_numbered_parts_in_order(self):
        names = [f"Scenes/Agreement.Matches/scene{i}" for i in range(5)]
        self.assertEqual(groups.groups(names, 2), [
            ("Scenes/Agreement.Matches (part 1 of 3)", names[0:2]),
            ("Scenes/Agreement.Matches (part 2 of 3)", names[2:4]),
            ("Scenes/Agreement.Matches (part 3 of 3)", names[4:5]),
        ])

    def test_bracket_arguments_hold_any_text(self):
        self.assertEqual(groups.bracket("a b"), "[=[a b]=]")
        self.assertEqual(groups.bracket("x]=]y"), "[==[x]=]y]==]")


def filters_in(groups_file):
    """Each add_test's --gtest_filter in a CTest file write_test_groups.py wrote."""
    with open(groups_file) as f:
        return re.findall(r"--gtest_filter=([^\]]*)\]", f.read())


def check_coverage(groups_file, program, gtest_filter):
    listed = groups.list_tests(program, gtest_filter, 60)
    run = collections.Counter(name for each in filters_in(groups_file) for name in each.split(":"))
    missing = sorted(set(listed) - set(run))
    twice = sorted(name for name, times in run.items() if times > 1)
    extra = sorted(set(run) - set(listed))
    problems = [f"{len(missing)} not run: {missing[:5]}"] if missing else []
    problems += [f"{len(twice)} run twice: {twice[:5]}"] if twice else []
    problems += [f"{len(extra)} not listed: {extra[:5]}"] if extra else []
    return listed, problems


class Coverage(unittest.TestCase):
    pairs = []

    def test_every_listed_test_runs_exactly_once(self):
        if not self.pairs:
            self.skipTest("no GROUPS_FILE PROGRAM[=FILTER] pairs given")
        for groups_file, spec in self.pairs:
            program, _, gtest_filter = spec.partition("=")
            with self.subTest(groups_file=groups_file):
                listed, problems = check_coverage(groups_file, program, gtest_filter)
                self.assertTrue(listed, f"{program} lists no tests")
                self.assertEqual(problems, [], groups_file)


if __name__ == "__main__":
    arguments = sys.argv[1:]
    if len(arguments) % 2:
        sys.exit("usage: test_write_test_groups.py [GROUPS_FILE PROGRAM[=FILTER]]...")
    Coverage.pairs = list(zip(arguments[0::2], arguments[1::2]))
    unittest.main(argv=[sys.argv[0]])
