#!/usr/bin/env python3
"""Writes the CTest file of a GoogleTest program's tests, a few to a process
(tests/cmake/TestGroups.cmake, docs/testing.md "The suite's time").

CTest's own discovery (gtest_discover_tests) starts the program once per test. A test of the
GL tiers then pays for the process, the driver's loading and the first context before it
draws anything: about 0.1 s, where most of the image tier's tests take 0.3 s. Here the
instances of one parameterised test (the techniques, the scenes) share a process, as do the
tests of one plain suite, up to --group-size of them in the program's own order, so that
each property still has its own CTest name and a failure names its test in the output.

    write_test_groups.py --executable EXE --prefix image. --output FILE
        [--filter GTEST_FILTER] [--group-size N] [--property NAME VALUE]...
"""
import argparse
import subprocess
import sys


def parse_listing(listing):
    """The "Suite.Test" names of --gtest_list_tests' output, in its order."""
    names = []
    suite = None
    for line in listing.splitlines():
        # "Suite." (a comment may follow), then "  Test" (a comment may follow).
        entry = line.split("#", 1)[0].rstrip()
        if not entry:
            continue
        if not line.startswith(" "):
            suite = entry
        elif suite is not None:
            names.append(suite + entry.strip())
    return names


def list_tests(executable, gtest_filter, timeout):
    """The program's tests in its own order."""
    command = [executable, "--gtest_list_tests"]
    if gtest_filter:
        command.append("--gtest_filter=" + gtest_filter)
    listing = subprocess.run(command, capture_output=True, text=True, timeout=timeout, check=True).stdout
    return parse_listing(listing)


def group_key(name):
    """A parameterised test's instances share a key (their name without the parameter); a
    plain test shares its suite's."""
    suite, test = name.split(".", 1)
    return suite + "." + test.rsplit("/", 1)[0] if "/" in test else suite


def groups(names, size):
    """(CTest name without the prefix, [test names]) in the program's order."""
    by_key = {}
    for name in names:
        by_key.setdefault(group_key(name), []).append(name)
    result = []
    for key, members in by_key.items():
        parts = [members[i:i + size] for i in range(0, len(members), size)]
        for index, part in enumerate(parts):
            label = key if len(parts) == 1 else f"{key} (part {index + 1} of {len(parts)})"
            result.append((label, part))
    return result


def bracket(text):
    """A CMake bracket argument holding `text` verbatim."""
    equals = "="
    while "]" + equals + "]" in text:
        equals += "="
    return "[" + equals + "[" + text + "]" + equals + "]"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--executable", required=True)
    parser.add_argument("--prefix", required=True)
    parser.add_argument("--output", required=True)
    parser.add_argument("--filter", default="")
    parser.add_argument("--group-size", type=int, default=8)
    parser.add_argument("--timeout", type=float, default=60)
    parser.add_argument("--property", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"))
    args = parser.parse_args()
    if args.group_size < 1:
        parser.error("--group-size must be at least 1")
    try:
        names = list_tests(args.executable, args.filter, args.timeout)
    except (OSError, subprocess.SubprocessError) as error:
        sys.exit(f"write_test_groups.py: cannot list the tests of {args.executable}: {error}")
    lines = []
    for label, members in groups(names, args.group_size):
        name = bracket(args.prefix + label)
        lines.append(f"add_test({name} {bracket(args.executable)} {bracket('--gtest_filter=' + ':'.join(members))})")
        properties = " ".join(f"{key} {bracket(value)}" for key, value in args.property)
        if properties:
            lines.append(f"set_tests_properties({name} PROPERTIES {properties})")
    with open(args.output, "w") as out:
        out.write("# Written by tests/cmake/write_test_groups.py after each build of the program.\n")
        out.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
