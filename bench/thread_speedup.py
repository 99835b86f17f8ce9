#!/usr/bin/env python3
"""What a second thread gives tioa-check: one thread against N, alternating, several rounds.

On a shared machine the wall time of one run moves by a third from one minute to the next
(other tenants' load, memory traffic, the clock), so one pair of runs says little about a
speed-up. This runs `-j 1` and `-j N` in turn, ROUNDS times, and prints:

- each pair: the wall and CPU seconds (user + system) of both runs, and the pair's speed-up
  (wall of -j 1 over wall of -j N, two runs a few seconds apart);
- the median of the pairs' speed-ups, and the speed-up of the fastest runs (the least
  disturbed of each kind);
- how much more CPU time the N threads spend in all than one thread (the work threads add:
  waits, contention for caches and memory).

Every run must report the same states and edges (the explorer's counts do not depend on the
number of threads); otherwise MISMATCH and exit 1.

Usage:
  bench/thread_speedup.py                          # Fischer N=9, -j 2, 8 rounds
  bench/thread_speedup.py --rounds 12 --threads 2 --binary build/cli/tioa-check
  bench/thread_speedup.py --model fischer --param N=10 --prop mutex

Exit codes: 0 the counts agree, 1 a run failed or the counts differ, 2 usage error or
/usr/bin/time missing (apt-get install time).
Python 3, standard library only.
"""

import argparse
import json
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
TIME = "/usr/bin/time"


def run(binary, model, params, prop, threads):
    """One run: (wall s, cpu s, states, edges), or raises RuntimeError."""
    command = [binary, "check", model, "--prop", prop, "--json", "--trace", "none",
               "--por", "off", "-j", str(threads)]
    for p in params:
        command += ["-p", p]
    with tempfile.NamedTemporaryFile("r") as timing:
        done = subprocess.run([TIME, "-f", "%e %U %S", "-o", timing.name] + command,
                              capture_output=True, text=True)
        figures = timing.read().split()
    if done.returncode not in (0, 1) or len(figures) < 3:
        raise RuntimeError(f"{' '.join(command)}: exit {done.returncode}: {done.stderr.strip()}")
    try:
        prop_report = json.loads(done.stdout)["properties"][0]
    except (ValueError, KeyError, IndexError) as error:
        raise RuntimeError(f"{' '.join(command)}: no report on stdout ({error})") from error
    wall, user, system = (float(x) for x in figures[-3:])
    return wall, user + system, prop_report["states"], prop_report["edges"]


def ratio(a, b):
    """a / b, with b at least /usr/bin/time's resolution (a tiny run takes 0.00 s)."""
    return a / max(b, 0.01)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--binary", default=str(REPO / "build" / "cli" / "tioa-check"))
    parser.add_argument("--model", default="fischer")
    parser.add_argument("--param", action="append", help="NAME=VALUE (default N=9)")
    parser.add_argument("--prop", default="mutex")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--rounds", type=int, default=8)
    args = parser.parse_args()
    if args.threads < 2 or args.rounds < 1:
        print("thread_speedup.py: --threads must be at least 2 and --rounds at least 1",
              file=sys.stderr)
        return 2
    if not Path(TIME).is_file():
        print(f"thread_speedup.py: {TIME} is missing (apt-get install time)", file=sys.stderr)
        return 2
    if not Path(args.binary).is_file():
        print(f"thread_speedup.py: no binary at {args.binary} (build the tioa-check target)",
              file=sys.stderr)
        return 2
    params = args.param or ["N=9"]

    n = args.threads
    print(f"{args.model} {' '.join(params)} --prop {args.prop} --por off: -j 1 against -j {n}, "
          f"{args.rounds} rounds, alternating")
    print(f"{'round':>5} {'wall 1':>8} {'wall ' + str(n):>8} {'speed-up':>9} "
          f"{'cpu 1':>8} {'cpu ' + str(n):>8} {'cpu +':>7}")
    pairs, counts = [], set()
    try:
        for r in range(1, args.rounds + 1):
            one = run(args.binary, args.model, params, args.prop, 1)
            many = run(args.binary, args.model, params, args.prop, n)
            counts.update({one[2:], many[2:]})
            pairs.append((one, many))
            print(f"{r:>5} {one[0]:>8.2f} {many[0]:>8.2f} {ratio(one[0], many[0]):>8.2f}x "
                  f"{one[1]:>8.2f} {many[1]:>8.2f} {100 * (ratio(many[1], one[1]) - 1):>6.0f}%")
    except RuntimeError as error:
        print(f"thread_speedup.py: {error}", file=sys.stderr)
        return 1
    speedups = [ratio(one[0], many[0]) for one, many in pairs]
    fastest_one = min(one[0] for one, _ in pairs)
    fastest_many = min(many[0] for _, many in pairs)
    extra_cpu = statistics.median(ratio(many[1], one[1]) - 1 for one, many in pairs)
    print(f"median speed-up of the pairs: {statistics.median(speedups):.2f}x "
          f"(from {min(speedups):.2f}x to {max(speedups):.2f}x)")
    print(f"fastest runs: {fastest_one:.2f} s against {fastest_many:.2f} s, "
          f"{ratio(fastest_one, fastest_many):.2f}x")
    print(f"CPU time of {n} threads over one (median): {100 * extra_cpu:+.0f}%")
    if len(counts) != 1:
        print(f"MISMATCH: states and edges differ between runs: {sorted(counts)}")
        return 1
    states, edges = counts.pop()
    print(f"states {states}, edges {edges} in every run")
    return 0


if __name__ == "__main__":
    sys.exit(main())
