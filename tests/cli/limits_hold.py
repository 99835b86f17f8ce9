#!/usr/bin/env python3
"""Whether --max-memory, --max-seconds and --max-states hold for every property (issue 17).

Each case is one property on an instance that needs more than the limits given to it
(limits_cases.json, chosen from `--measure`). For each case and limit the property is run
with that limit alone, and must stop *incomplete* (exit 3) within it:

- memory: the resident memory the run adds beyond its unavoidable start is within 10% of
  --max-memory. The start is measured, not assumed: the peak of building the model and
  exploring one state (`explore --max-states 1`);
- time: the run ends within one second of --max-seconds, beyond that start's time;
- states: the states the report gives are at most --max-states.

  limits_hold.py TIOA_CHECK [--model M]...   check the cases (of the models given)
  limits_hold.py TIOA_CHECK --measure        each case unlimited (up to 40 s): its needs

Exit 0 when every limit held, 1 otherwise (each failure on one line).
"""

import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
MIB = 1024 * 1024


def run_measured(tool, args):
    """Runs tioa-check: its exit code, wall seconds, peak resident bytes (its own, from
    wait4), JSON report and standard error."""
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        started = time.monotonic()
        child = subprocess.Popen([tool] + args + ["--json", "--threads", "2"], stdout=out,
                                 stderr=err)
        _, status, usage = os.wait4(child.pid, 0)
        seconds = time.monotonic() - started
        child.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        try:
            report = json.loads(out.read())
        except ValueError:
            report = None
        return (child.returncode, seconds, usage.ru_maxrss * 1024, report,
                err.read().decode(errors="replace").strip())


def command(case):
    args = ["check", case["model"]]
    if case.get("params"):
        args += ["-p", case["params"]]
    return args + ["--prop", case["prop"], "--trace", "none"]


def name(case):
    return f'{case["model"]} {case.get("params", "")} {case["prop"]}'.replace("  ", " ")


def states_of(report):
    if not report or not report.get("properties"):
        return None
    return report["properties"][0].get("states")


def start_of(tool, case):
    """The unavoidable start of a run: the peak resident bytes and wall seconds of building
    the model and exploring one state of it."""
    args = ["explore", case["model"]] + (["-p", case["params"]] if case.get("params") else [])
    code, seconds, peak, _, err = run_measured(tool, args + ["--max-states", "1", "--trace", "none"])
    if code not in (0, 1, 3):
        raise RuntimeError(f"{name(case)}: explore --max-states 1 gave exit {code}: {err[:200]}")
    return peak, seconds


def check_case(tool, case, failures):
    base_args = command(case)
    base_peak, base_seconds = start_of(tool, case)
    lines = []
    if "memory" in case:
        limit = case["memory"] * MIB
        code, _, peak, _, err = run_measured(tool, base_args + ["--max-memory", str(case["memory"])])
        added = max(0, peak - base_peak)
        lines.append(f"memory {case['memory']} MiB: added {added / MIB:.0f} MiB, exit {code}")
        if code != 3:
            failures.append(f"{name(case)}: --max-memory {case['memory']} gave exit {code}, not 3")
        if added > 1.1 * limit:
            failures.append(f"{name(case)}: --max-memory {case['memory']}: the run added "
                            f"{added / MIB:.0f} MiB (start {base_peak / MIB:.0f} MiB), over 110%")
    if "seconds" in case:
        code, seconds, _, _, err = run_measured(tool, base_args + ["--max-seconds",
                                                                 str(case["seconds"])])
        lines.append(f"time {case['seconds']} s: {seconds:.1f} s, exit {code}")
        # A violation found before the time is up is the right answer too (exit 1: lemma-6.4
        # on a loaded machine may reach its counterexample within the second); what must
        # not happen is "holds", another exit, or a run past the limit.
        if code not in (1, 3):
            failures.append(f"{name(case)}: --max-seconds {case['seconds']} gave exit {code}, "
                            "not 3 (or 1)")
        if seconds > case["seconds"] + 1 + base_seconds:
            failures.append(f"{name(case)}: --max-seconds {case['seconds']}: ran {seconds:.1f} s "
                            f"(start {base_seconds:.1f} s), over the limit by more than 1 s")
    if "states" in case:
        code, _, _, report, err = run_measured(tool, base_args + ["--max-states",
                                                                str(case["states"])])
        states = states_of(report)
        lines.append(f"states {case['states']}: {states}, exit {code}")
        if code != 3:
            failures.append(f"{name(case)}: --max-states {case['states']} gave exit {code}, not 3")
        if states is None or states > case["states"]:
            failures.append(f"{name(case)}: --max-states {case['states']}: reported {states} states")
    print(f"{name(case)}: start {base_peak / MIB:.0f} MiB {base_seconds:.1f} s; " + "; ".join(lines),
          flush=True)


def measure(tool, case):
    code, seconds, peak, report, err = run_measured(tool, command(case) + ["--max-seconds", "40"])
    base_peak, base_seconds = start_of(tool, case)
    verdict = report["properties"][0]["verdict"] if report and report.get("properties") else err[:80]
    print(f"{name(case)}: {verdict}, {seconds:.1f} s, {peak / MIB:.0f} MiB peak, "
          f"start {base_peak / MIB:.0f} MiB {base_seconds:.1f} s, states {states_of(report)}",
          flush=True)


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    tool = sys.argv[1]
    rest = sys.argv[2:]
    with open(os.path.join(HERE, "limits_cases.json")) as f:
        cases = json.load(f)["cases"]
    models = [rest[i + 1] for i, a in enumerate(rest) if a == "--model"]
    if models:
        cases = [c for c in cases if c["model"] in models]
        if not cases:
            print(f"no case for the models {', '.join(models)}", file=sys.stderr)
            return 2
    if "--measure" in rest:
        for case in cases:
            measure(tool, case)
        return 0
    failures = []
    for case in cases:
        if not any(limit in case for limit in ("memory", "seconds", "states")):
            failures.append(f"{name(case)}: the case gives no limit to check")
        check_case(tool, case, failures)
    for f in failures:
        print("FAIL " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
