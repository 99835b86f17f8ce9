#!/usr/bin/env python3
"""Distributed exploration (issue 18): one process against `mpirun -np N` on the same
machine, for invariants (the checks that run distributed). Prints, per instance and
number of ranks: states, edges, wall seconds (whole run) and the peak resident memory
of each rank (MiB, /usr/bin/time around each rank), and checks that the counts agree.

usage: bench/mpi_bench.py [--tioa build/cli/tioa-check] [--ranks 2] [--only NAME]
"""
import argparse
import json
import os
import re
import subprocess
import sys
import time

CASES = {
    "fischer-8": ["check", "fischer", "-p", "N=8", "--prop", "mutex"],
    "fischer-9": ["check", "fischer", "-p", "N=9", "--prop", "mutex"],
    "fischer-10": ["check", "fischer", "-p", "N=10", "--prop", "mutex"],
    "ring-8-9": ["check", "token-ring", "-p", "N=8,K=9", "--prop", "some-privileged"],
    # bench_vlayer's 2x2-r2-n4 time-lock check, in full (--por off): 55.6 million states
    "vlayer-2x2-r2": ["check", "vlayer-mc", "-p", "rows=2,robots=2", "--prop", "no-timelock"],
    # the same with the zero-time reduction (bench/README.md: 622,196 states in one process)
    "vlayer-2x2-r2-por": ["check", "vlayer-mc", "-p", "rows=2,robots=2", "--prop", "no-timelock",
                          "--por", "on"],
    "vlayer-2x2-r3-por": ["check", "vlayer-mc", "-p", "rows=2,robots=3", "--prop", "no-timelock",
                          "--por", "on"],
}


def run(prefix, tioa, case):
    por = [] if "--por" in CASES[case] else ["--por", "off"]  # the full graph unless asked
    command = prefix + ["/usr/bin/time", "-f", "RSS %M", tioa] + CASES[case] + [
        "--json", "--trace", "none", "-j", "1"] + por
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    began = time.monotonic()
    done = subprocess.run(command, capture_output=True, text=True, env=env)
    wall = time.monotonic() - began
    prop = json.loads(done.stdout)["properties"][0]
    rss = [int(x) // 1024 for x in re.findall(r"RSS (\d+)", done.stderr)]
    return prop, wall, rss


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tioa", default="build/cli/tioa-check")
    ap.add_argument("--ranks", type=int, action="append")
    ap.add_argument("--only", action="append")
    args = ap.parse_args()
    ranks = args.ranks or [2]
    bad = 0
    print(f"{'instance':12} {'ranks':>5} {'states':>12} {'edges':>13} {'wall s':>8} "
          f"{'MiB per rank':>20}")
    for case in args.only or ["fischer-9", "fischer-10"]:
        one, wall, rss = run([], args.tioa, case)
        print(f"{case:12} {1:5} {one['states']:12,} {one['edges']:13,} {wall:8.2f} "
              f"{' '.join(map(str, rss)):>20}")
        for n in ranks:
            many, wall, rss = run(["mpirun", "--oversubscribe", "-np", str(n)], args.tioa, case)
            same = (many["states"], many["edges"], many["verdict"]) == (
                one["states"], one["edges"], one["verdict"])
            bad += not same
            print(f"{case:12} {n:5} {many['states']:12,} {many['edges']:13,} {wall:8.2f} "
                  f"{' '.join(map(str, rss)):>20}{'' if same else '  MISMATCH'}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
