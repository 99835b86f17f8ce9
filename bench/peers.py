#!/usr/bin/env python3
"""tioa-check side by side with SPIN and Rumur on the peer models of ../shared/peers.

For each instance (fischer-N with A=1 B=2, ring-N-K) it runs, one at a time:

- tioa-check: `check MODEL --prop P --json --por off -j THREADS` (the full graph, as the peers
  explore it), where P is the model's invariant
  (`mutex` for fischer, from the start state; `some-privileged` for the token ring, whose
  invariant check explores U(A), every one of the K^N valuations as a start state: the start
  set the peer models have);
- SPIN, its fastest variant: the one-process model X_1p.pml, `spin -a`, pan.c compiled with
  -DSAFETY -DNOREDUCE, `./pan -m500000 -wW` (W sized for twice the expected states);
- Rumur, one thread: `rumur --deadlock-detection off --threads 1`, compiled with -O3.

Each checker run (not the compilation) is timed as a whole process with `/usr/bin/time -v`:
wall seconds and peak resident memory. The table gives states, edges, wall seconds, millions
of states per second, bytes per state (peak RSS / states) and, for tioa-check, its states/s
over the faster peer's and its bytes/state over the smaller peer's. The state and edge
counts of the three must agree (SPIN: see the note under the table); otherwise MISMATCH.

Usage:
  bench/peers.py                        # fischer-8, -9, -10, ring-7-8, ring-8-9
  bench/peers.py --quick                # fischer-6, fischer-7, ring-6-7: about ten seconds
  bench/peers.py --only fischer-8 --only ring-7-8 --json rows.json
  bench/peers.py --skip-peers --threads 2

Exit codes: 0 all counts agree, 1 MISMATCH or a run failed, 2 usage error or a tool
missing, 3 some run timed out (and nothing else went wrong).
Python 3, standard library only.
"""

import argparse
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
TIME = "/usr/bin/time"
COMPILE_TIMEOUT = 600  # seconds for each compilation step, whatever --timeout says

DEFAULT_INSTANCES = ["fischer-8", "fischer-9", "fischer-10", "ring-7-8", "ring-8-9"]
QUICK_INSTANCES = ["fischer-6", "fischer-7", "ring-6-7"]

# Fischer (A=1, B=2) state counts known from earlier runs (bench/README.md, ../shared/peers),
# used only to size SPIN's hash table when tioa-check has not counted the states first.
FISCHER_STATES = {6: 65_299, 7: 364_129, 8: 2_017_775, 9: 11_112_321, 10: 60_832_779}


class Instance:
    def __init__(self, name, model, params, base, prop):
        self.name = name          # fischer-8, ring-7-8
        self.model = model        # tioa-check's model name
        self.params = params      # tioa-check's parameters, "N=8,A=1,B=2"
        self.base = base          # the peer models' file stem, fischer_N8
        self.prop = prop          # tioa-check's property
        self.is_ring = model == "token-ring"

    def expected_states(self):
        if self.is_ring:
            n, k = (int(v.split("=")[1]) for v in self.params.split(","))
            return k ** n
        n = int(self.params.split(",")[0].split("=")[1])
        if n in FISCHER_STATES:
            return FISCHER_STATES[n]
        # Each process more multiplies the count by about 5.5 around N = 10.
        return int(FISCHER_STATES[10] * 5.5 ** (n - 10))


def parse_instance(name):
    m = re.fullmatch(r"fischer-(\d+)", name)
    if m:
        n = int(m.group(1))
        if not 2 <= n <= 12:
            raise ValueError("fischer-N takes N in 2..12")
        return Instance(name, "fischer", "N=%d,A=1,B=2" % n, "fischer_N%d" % n, "mutex")
    m = re.fullmatch(r"ring-(\d+)-(\d+)", name)
    if m:
        n, k = int(m.group(1)), int(m.group(2))
        if not (2 <= n <= 20 and 2 <= k <= 64):
            raise ValueError("ring-N-K takes N in 2..20 and K in 2..64")
        return Instance(name, "token-ring", "N=%d,K=%d" % (n, k), "ring_N%d_K%d" % (n, k),
                        "some-privileged")
    raise ValueError("unknown instance '%s' (names like fischer-8, ring-7-8)" % name)


def fail_usage(message):
    print("peers.py: " + message, file=sys.stderr)
    sys.exit(2)


def progress(message):
    print(message, file=sys.stderr, flush=True)


class Run:
    """One checker run: status 'ok', 'timeout' or 'failed', and what it measured."""

    def __init__(self, checker):
        self.checker = checker
        self.status = "ok"
        self.reason = ""
        self.states = None        # as the checker prints them
        self.edges = None
        self.wall = None          # seconds, /usr/bin/time
        self.rss_kib = None       # peak resident set, /usr/bin/time
        self.own_seconds = None   # the checker's own figure
        self.command = ""
        self.raw = {}             # SPIN's stored/matched/transitions

    def fail(self, reason):
        self.status = "failed"
        self.reason = reason
        return self

    def rate(self):
        if self.status != "ok" or not self.wall:
            return None
        return self.states / self.wall

    def bytes_per_state(self):
        if self.status != "ok" or not self.states:
            return None
        return self.rss_kib * 1024 / self.states

    def to_json(self):
        return {
            "checker": self.checker, "status": self.status, "reason": self.reason,
            "states": self.states, "edges": self.edges, "wall_seconds": self.wall,
            "peak_rss_kib": self.rss_kib, "own_seconds": self.own_seconds,
            "states_per_second": self.rate(), "bytes_per_state": self.bytes_per_state(),
            "command": self.command, "raw": self.raw,
        }


def run_step(command, cwd, timeout):
    """Runs a command to the end or the timeout (killing its process group).
    Returns (returncode or None on timeout, stdout, stderr)."""
    proc = subprocess.Popen(command, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, start_new_session=True)
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, err = proc.communicate()
        return None, out, err
    except KeyboardInterrupt:  # its own session does not see the terminal's Ctrl-C
        os.killpg(proc.pid, signal.SIGKILL)
        raise
    return proc.returncode, out, err


def measured(run, command, cwd, timeout):
    """Runs the checker under /usr/bin/time -v; fills run.wall and run.rss_kib.
    Returns (returncode, stdout, stderr), returncode None on a timeout."""
    run.command = " ".join(command)
    time_file = os.path.join(cwd, "time-v.txt")
    code, out, err = run_step([TIME, "-v", "-o", time_file] + command, cwd, timeout)
    if code is None:
        run.status = "timeout"
        run.reason = "over %g s" % timeout
        return None, out, err
    try:
        with open(time_file) as f:
            report = f.read()
    except OSError:
        report = ""
    wall = re.search(r"Elapsed \(wall clock\) time.*?: (?:(\d+):)?(\d+):([\d.]+)", report)
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", report)
    if wall and rss:
        hours = int(wall.group(1) or 0)
        run.wall = hours * 3600 + int(wall.group(2)) * 60 + float(wall.group(3))
        run.rss_kib = int(rss.group(1))
    return code, out, err


def last_lines(text, count=3):
    lines = [line.strip() for line in text.strip().splitlines() if line.strip()]
    return " | ".join(lines[-count:])


def number(pattern, text):
    m = re.search(pattern, text)
    return int(m.group(1).replace(",", "")) if m else None


def run_tioa(inst, tioa, threads, work, timeout):
    run = Run("tioa-check")
    cwd = work / "tioa" / inst.name
    cwd.mkdir(parents=True, exist_ok=True)
    command = [str(tioa), "check", inst.model, "-p", inst.params, "--prop", inst.prop,
               "--json", "--trace", "none", "--por", "off", "-j", str(threads)]
    progress("[%s] tioa-check: %s" % (inst.name, " ".join(command)))
    code, out, err = measured(run, command, str(cwd), timeout)
    if code is None:
        return run
    try:
        prop = json.loads(out)["properties"][0]
    except (ValueError, KeyError, IndexError):
        return run.fail("exit %d, no JSON: %s" % (code, last_lines(err or out)))
    if prop.get("verdict") != "holds":
        return run.fail("verdict %s: %s" % (prop.get("verdict"), prop.get("message")))
    run.states, run.edges, run.own_seconds = prop["states"], prop["edges"], prop["seconds"]
    if run.wall is None:
        return run.fail("no /usr/bin/time report")
    return run


def model_file(inst, suffix, peers, work):
    """The peer model X{suffix} from peers/models, or generated with gen.py into work/models."""
    name = inst.base + suffix
    existing = peers / "models" / name
    if existing.is_file():
        return existing
    generated = work / "models" / name
    if not generated.is_file():
        kind, numbers = inst.name.split("-", 1)
        arguments = [sys.executable, str(peers / "gen.py"), kind] + numbers.split("-")
        progress("[%s] generating with %s" % (inst.name, " ".join(arguments[1:])))
        env = dict(os.environ, PEER_MODELS_OUT=str(work / "models"))
        subprocess.run(arguments, env=env, check=True, stdout=subprocess.DEVNULL)
    return generated


def compile_steps(run, steps, cwd):
    """Runs the compilation commands; returns False (run marked) when one fails."""
    for command in steps:
        code, out, err = run_step(command, str(cwd), COMPILE_TIMEOUT)
        if code is None:
            run.status = "timeout"
            run.reason = "compilation over %g s" % COMPILE_TIMEOUT
            return False
        if code != 0:
            run.fail("%s failed: %s" % (command[0], last_lines(err or out)))
            return False
    return True


def peer_run(checker, inst, suffix, peers, work):
    """The run of one peer on one instance: its record, its directory, its model file."""
    run = Run(checker)
    cwd = work / checker / inst.name
    cwd.mkdir(parents=True, exist_ok=True)
    model = model_file(inst, suffix, peers, work)
    progress("[%s] %s: compiling %s" % (inst.name, checker, model.name))
    return run, cwd, model


def run_spin(inst, peers, work, timeout, expected):
    run, cwd, model = peer_run("spin", inst, "_1p.pml", peers, work)
    if not compile_steps(run, [
            ["spin", "-a", str(model)],
            ["gcc", "-O2", "-DSAFETY", "-DNOREDUCE", "-DVECTORSZ=1024", "-o", "pan", "pan.c"]],
            cwd):
        return run
    width = max(20, min(32, math.ceil(math.log2(2 * max(expected, 1)))))
    command = ["./pan", "-m500000", "-w%d" % width]
    progress("[%s] spin: %s" % (inst.name, " ".join(command)))
    code, out, err = measured(run, command, str(cwd), timeout)
    if code is None:
        return run
    stored = number(r"(\d+) states, stored", out)
    matched = number(r"(\d+) states, matched", out)
    transitions = number(r"(\d+) transitions", out)
    errors = number(r"errors: (\d+)", out)
    if "max search depth too small" in out:
        return run.fail("max search depth too small (-m500000): the search was cut")
    if "out of memory" in out or "out of memory" in err:
        return run.fail("out of memory")
    if code != 0 or None in (stored, matched, transitions) or errors:
        return run.fail("exit %d, errors %s: %s" % (code, errors, last_lines(out + err)))
    elapsed = re.search(r"pan: elapsed time ([\d.e+]+) seconds", out)
    run.own_seconds = float(elapsed.group(1)) if elapsed else None
    run.states, run.edges = stored, transitions
    run.raw = {"states_stored": stored, "states_matched": matched, "transitions": transitions,
               "hash_width": width}
    if run.wall is None:
        return run.fail("no /usr/bin/time report")
    return run


def run_rumur(inst, peers, work, timeout):
    run, cwd, model = peer_run("rumur", inst, ".m", peers, work)
    if not compile_steps(run, [
            ["rumur", "--deadlock-detection", "off", "--threads", "1", str(model),
             "-o", "checker.c"],
            ["gcc", "-std=c11", "-march=native", "-O3", "-o", "checker", "checker.c",
             "-lpthread"]], cwd):
        return run
    progress("[%s] rumur: ./checker" % inst.name)
    code, out, err = measured(run, ["./checker"], str(cwd), timeout)
    if code is None:
        return run
    m = re.search(r"([\d,]+) states, ([\d,]+) rules fired in ([\d.]+)s", out)
    if code != 0 or not m or "No error found" not in out:
        return run.fail("exit %d: %s" % (code, last_lines(out + err)))
    run.states = int(m.group(1).replace(",", ""))
    run.edges = int(m.group(2).replace(",", ""))
    run.own_seconds = float(m.group(3))
    if run.wall is None:
        return run.fail("no /usr/bin/time report")
    return run


def spin_counts(inst, run):
    """SPIN's figures as the other two count: the ring's 'states stored' has one root state
    more (before the atomic init), and its edges are 'states matched'; on Fischer the edges
    are 'transitions' - 1 (peers/gen.py)."""
    if inst.is_ring:
        return run.states - 1, run.raw["states_matched"]
    return run.states, run.edges - 1


def mismatches(inst, runs):
    """The disagreements among the runs that finished, as lines."""
    counted = []
    for run in runs:
        if run.status != "ok":
            continue
        states, edges = spin_counts(inst, run) if run.checker == "spin" else (run.states, run.edges)
        counted.append((run.checker, states, edges))
    lines = []
    for what, index in (("states", 1), ("edges", 2)):
        values = {entry[index] for entry in counted}
        if len(values) > 1:
            lines.append("MISMATCH %s %s: %s" % (inst.name, what, ", ".join(
                "%s %d" % (entry[0], entry[index]) for entry in counted)))
    return lines


def ratio(value):
    return "%.2fx" % value if value is not None else ""


def table_row(inst, run, speed="", memory=""):
    if run.status != "ok":
        text = "TIMEOUT (%s)" % run.reason if run.status == "timeout" else "FAILED: " + run.reason
        return "%-11s %-11s %s" % (inst.name, run.checker, text)
    rate = run.rate()
    bps = run.bytes_per_state()
    return "%-11s %-11s %13s %14s %8.2f %10s %8s %9s %9s" % (
        inst.name, run.checker, format(run.states, ","), format(run.edges, ","), run.wall,
        "%.2f" % (rate / 1e6) if rate else "-", "%.0f" % bps if bps is not None else "-",
        speed, memory)


HEADER = "%-11s %-11s %13s %14s %8s %10s %8s %9s %9s" % (
    "instance", "checker", "states", "edges", "wall s", "Mstates/s", "B/state", "x rate",
    "x B/state")


def main():
    parser = argparse.ArgumentParser(
        description="tioa-check side by side with SPIN and Rumur on the peer models "
                    "(../shared/peers); see the docstring of this file.")
    parser.add_argument("--only", action="append", metavar="NAME",
                        help="an instance, fischer-N or ring-N-K (repeatable)")
    parser.add_argument("--quick", action="store_true",
                        help="the small instances %s" % ", ".join(QUICK_INSTANCES))
    parser.add_argument("--tioa", default=str(REPO / "build" / "cli" / "tioa-check"),
                        help="the tioa-check binary (default: build/cli/tioa-check)")
    parser.add_argument("--threads", type=int, default=1,
                        help="tioa-check's threads (default 1: one core each)")
    parser.add_argument("--peers-dir", default=str(REPO.parent / "shared" / "peers"),
                        help="the peer models and gen.py (default ../shared/peers)")
    parser.add_argument("--work-dir",
                        help="where generated models and compiled peers go (default: a "
                             "temporary directory, removed at the end)")
    parser.add_argument("--skip-peers", action="store_true", help="run tioa-check only")
    parser.add_argument("--timeout", type=float, default=600,
                        help="seconds per run (default 600); a run over it is reported "
                             "as a timeout")
    parser.add_argument("--json", metavar="FILE", help="also write the rows as JSON to FILE")
    args = parser.parse_args()

    names = args.only or (QUICK_INSTANCES if args.quick else DEFAULT_INSTANCES)
    try:
        instances = [parse_instance(name) for name in names]
    except ValueError as error:
        fail_usage(str(error))
    if args.threads < 1:
        fail_usage("--threads takes a number >= 1")
    if args.timeout <= 0:
        fail_usage("--timeout takes a number of seconds > 0")
    tioa = Path(args.tioa).resolve()
    if not os.access(tioa, os.X_OK):
        fail_usage("no tioa-check binary at %s (build the project, or pass --tioa PATH)" % tioa)
    peers = Path(args.peers_dir).resolve()
    needed = [] if args.skip_peers else ["spin", "rumur", "gcc"]
    missing = [tool for tool in needed if shutil.which(tool) is None]
    if not os.access(TIME, os.X_OK):
        missing.append(TIME)
    if missing:
        fail_usage("missing %s: apt-get install -y spin rumur time" % ", ".join(missing))
    if not args.skip_peers and not (peers / "gen.py").is_file():
        fail_usage("no gen.py in %s (pass --peers-dir)" % peers)

    temporary = None
    if args.work_dir:
        work = Path(args.work_dir).resolve()
        work.mkdir(parents=True, exist_ok=True)
    else:
        temporary = tempfile.mkdtemp(prefix="tioa-peers-")
        work = Path(temporary)

    load = os.getloadavg()
    progress("peers.py: %s, -j %d, %d cores, load %.2f %.2f %.2f, work dir %s" % (
        tioa, args.threads, os.cpu_count() or 0, load[0], load[1], load[2], work))
    rows, lines, problems = [], [], []
    timed_out = failed = False
    try:
        for inst in instances:
            runs = [run_tioa(inst, tioa, args.threads, work, args.timeout)]
            if not args.skip_peers:
                expected = runs[0].states if runs[0].status == "ok" else inst.expected_states()
                runs.append(run_spin(inst, peers, work, args.timeout,
                                     expected + (1 if inst.is_ring else 0)))
                runs.append(run_rumur(inst, peers, work, args.timeout))
            timed_out |= any(run.status == "timeout" for run in runs)
            failed |= any(run.status == "failed" for run in runs)
            problems += mismatches(inst, runs)

            tioa_run, peer_runs = runs[0], [run for run in runs[1:] if run.status == "ok"]
            speed = memory = None
            if tioa_run.status == "ok" and peer_runs:
                rates = [run.rate() for run in peer_runs]
                if tioa_run.rate() and all(rates):  # no ratio when a run was too short to time
                    speed = tioa_run.rate() / max(rates)
                memory = tioa_run.bytes_per_state() / min(
                    run.bytes_per_state() for run in peer_runs)
            instance_lines = [table_row(inst, tioa_run, ratio(speed), ratio(memory))]
            instance_lines += [table_row(inst, run) for run in runs[1:]]
            for line in instance_lines:
                progress(line)
            lines += instance_lines
            for run in runs:
                row = dict(run.to_json(), instance=inst.name)
                if run is tioa_run:
                    row["rate_over_faster_peer"] = speed
                    row["bytes_per_state_over_smaller_peer"] = memory
                rows.append(row)
    finally:
        if temporary:
            shutil.rmtree(temporary, ignore_errors=True)

    print(HEADER)
    for line in lines:
        print(line)
    print()
    print("wall s and peak memory (B/state = peak RSS / states) of the whole process, "
          "/usr/bin/time -v; tioa-check -j %d, SPIN and Rumur one core." % args.threads)
    print("x rate: tioa-check's states/s over the faster peer's (above 1: tioa-check is "
          "faster); x B/state: its bytes per state over the smaller peer's (above 1: it "
          "uses more). Both over the peers that finished.")
    if not args.skip_peers:
        print("SPIN's figures are as it prints them: states = 'states stored', edges = "
              "'transitions'. On the ring 'states stored' is K^N + 1 (the root state "
              "before the atomic init) and the edges are 'states matched'; on fischer "
              "the edges are 'transitions' - 1. The check below takes this into account.")
    for line in problems:
        print(line)
    if not problems and not args.skip_peers:
        print("counts: the checkers that finished agree on every instance")

    if args.json:
        with open(args.json, "w") as f:
            json.dump({"tioa": str(tioa), "threads": args.threads, "cores": os.cpu_count(),
                       "load_average_at_start": load, "timeout": args.timeout,
                       "date": time.strftime("%Y-%m-%dT%H:%M:%S%z"), "rows": rows,
                       "mismatches": problems}, f, indent=2)
            f.write("\n")
    if problems or failed:
        return 1
    return 3 if timed_out else 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except KeyboardInterrupt:
        print("peers.py: interrupted", file=sys.stderr)
        sys.exit(130)
