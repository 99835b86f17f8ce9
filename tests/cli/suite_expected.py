#!/usr/bin/env python3
"""The whole default suite (the README's main job), run once, with everything CI wants of it.

Usage: suite_expected.py TIOA_CHECK

Runs `tioa-check suite --json` and checks, entry by entry:
- the verdict is the one the entry expects (and the report says all_as_expected);
- an entry expected to be violated shows its counterexample: a trace with steps, or, for a
  lemma over a family of round-level instances (kind round-lemma), a note naming its
  smallest counterexample;
- a verdict that holds covered what it claims: its coverage is not sampled.
One line per entry is printed (the suite's table, shortened), then the failures.

The text table itself is checked on the two small models by cli.suite_table; this run is
the one that sees every entry. Exit 0 when all is as expected, 1 otherwise.
"""

import json
import subprocess
import sys


def counterexample_shown(result):
    if result.get("kind") == "round-lemma":
        return any("counterexample" in note for note in result.get("notes", []))
    trace = result.get("trace")
    return bool(trace) and len(trace.get("steps", [])) > 0


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    run = subprocess.run([sys.argv[1], "suite", "--json"], capture_output=True, text=True)
    if run.returncode != 0:
        print(f"FAIL suite --json: exit {run.returncode}: {run.stderr.strip()[:400]}")
        return 1
    report = json.loads(run.stdout)
    failures = []
    if report.get("all_as_expected") is not True:
        failures.append("the report does not say all_as_expected")
    entries = report.get("suite", [])
    if not entries:
        failures.append("the suite has no entry")
    for entry in entries:
        result = entry["result"]
        params = ",".join(f"{k}={v}" for k, v in entry.get("params", {}).items())
        label = f"{entry['model']} {entry['property']} [{params}]"
        print(f"{entry['model']:<18} {entry['property']:<26} {result['verdict']:<10} "
              f"expected {entry['expected']:<10} {result.get('states')} states "
              f"{result.get('seconds', 0):.2f} s", flush=True)
        if result["verdict"] != entry["expected"]:
            failures.append(f"{label}: {result['verdict']}, expected {entry['expected']}: "
                            f"{result.get('message', '')[:200]}")
        if result["verdict"] == "violated" and not counterexample_shown(result):
            failures.append(f"{label}: violated without its counterexample")
        if result["verdict"] == "holds" and result.get("coverage", {}).get("starts") == "sampled":
            failures.append(f"{label}: holds on sampled start states")
    for failure in failures:
        print("FAIL " + failure)
    print(f"suite_expected: {len(entries)} entries, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
