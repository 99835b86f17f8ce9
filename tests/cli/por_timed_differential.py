#!/usr/bin/env python3
"""The zero-time reduction where time can pass, against the full search (issue 14).

With --por on, the invariant and time-lock checks leave vlayer-mc's deliveries for later at
states where time can pass (they commute with a tick: checker/zero_time_reduction.hpp).
Whether a state is reachable where a delivery has (or has not) happened at a given time is
exactly what that could get wrong. So this checks invariants of the form

    not (A = a and B = b)

with A a variable the deliveries write (the pending masks and flags, V_u, M_u) and B one
that time changes (the VNs' clocks, the slots' ages, real time), on small instances, with
--por on and with --por off: the verdicts must be the same. On 1x2 with one robot every
pair of values (a, b) is checked; on the larger instances pairs are drawn (seeded: the same
draws every run). It also asks that both verdicts occur, so that the comparison is not
empty.

  por_timed_differential.py TIOA_CHECK

Exit 0 when every verdict agrees, 1 otherwise (each difference on one line), 2 on bad use.
"""

import json
import random
import subprocess
import sys

# Per instance: its parameters, how many pairs to draw (0: every pair), the variables
# deliveries write and those time changes, each with its values (value() below). The full
# graph of 2x2 takes about 2 s a check.
INSTANCES = [
    ("cols=2", 0,
     [("VBcast.vn_mask[0]", 0, 1), ("VBcast.vn_mask[1]", 0, 1), ("VN_0.V[1]", 0, 1),
      ("VN_1.V[0]", 0, 1), ("VBcast.cn_pending[0]", "bool")],
     [("VN_0.clock", 0, 5), ("VN_1.clock", 0, 5), ("VBcast.vn_age[0]", 0, 1),
      ("VBcast.vn_age[1]", 0, 1), ("RW.now", 0, 5), ("VBcast.cn_age[0]", 0, 1)]),
    ("cols=2,robots=2", 16,
     [("VBcast.vn_mask[0]", 0, 1), ("VBcast.vn_mask[1]", 0, 1), ("VN_0.V[1]", 0, 2),
      ("VN_1.V[0]", 0, 2), ("VBcast.cn_pending[1]", "bool"), ("VN_1.M[1]", -1, 15)],
     [("VN_0.clock", 0, 5), ("VN_1.clock", 0, 5), ("VBcast.vn_age[0]", 0, 1),
      ("VBcast.vn_age[1]", 0, 1), ("RW.now", 0, 5)]),
    ("rows=2,cols=2", 6,
     [("VBcast.vn_mask[0]", 0, 3), ("VBcast.vn_mask[2]", 0, 3), ("VN_0.V[2]", 0, 1),
      ("VN_3.V[2]", 0, 1)],
     [("VN_0.clock", 0, 5), ("VN_3.clock", 0, 5), ("VBcast.vn_age[2]", 0, 1), ("RW.now", 0, 5)]),
]


def values(variable):
    """Every value of the variable: (name, "bool") or (name, lo, hi), where lo = -1 is ⊥."""
    if variable[1] == "bool":
        return ["true", "false"]
    return ["bottom" if v < 0 else str(v) for v in range(variable[1], variable[2] + 1)]


def pairs(draw, count, written, timed):
    """Every pair of an assignment of a written and of a timed variable (count 0), or
    `count` drawn."""
    if count == 0:
        for a in written:
            for a_value in values(a):
                for b in timed:
                    for b_value in values(b):
                        yield (a[0], a_value), (b[0], b_value)
        return
    for _ in range(count):
        a, b = draw.choice(written), draw.choice(timed)
        yield (a[0], draw.choice(values(a))), (b[0], draw.choice(values(b)))


def verdict(tool, params, invariant, por):
    args = [tool, "check", "vlayer-mc", "-p", params, "--invariant", invariant, "--por", por,
            "--json", "--trace", "none", "--threads", "2"]
    run = subprocess.run(args, capture_output=True, text=True, check=False)
    if run.returncode not in (0, 1):
        raise RuntimeError(f"{' '.join(args)}: exit {run.returncode}: {run.stderr.strip()}")
    report = json.loads(run.stdout)
    return report["properties"][0]["verdict"]


def main(argv):
    if len(argv) != 2 or argv[1].startswith("-"):
        print("usage: por_timed_differential.py TIOA_CHECK", file=sys.stderr)
        return 2
    tool = argv[1]
    draw = random.Random(20261129)
    seen, differences = {"holds": 0, "violated": 0}, []
    for params, count, written, timed in INSTANCES:
        for (a, a_value), (b, b_value) in pairs(draw, count, written, timed):
            invariant = f"not ({a} = {a_value} and {b} = {b_value})"
            reduced = verdict(tool, params, invariant, "on")
            full = verdict(tool, params, invariant, "off")
            seen[full] = seen.get(full, 0) + 1
            if reduced != full:
                differences.append(f"{params} '{invariant}': --por on {reduced}, off {full}")
    for line in differences:
        print("DIFFERENT", line)
    print(f"{sum(seen.values())} invariants: {seen['holds']} hold, {seen['violated']} violated, "
          f"{len(differences)} different with --por on")
    if seen["holds"] == 0 or seen["violated"] == 0:
        print("the checks gave one verdict only: the comparison says little")
        return 1
    return 1 if differences else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
