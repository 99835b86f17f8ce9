#!/usr/bin/env python3
"""Distributed exploration (issue 18): under `mpirun -np N` every invariant, every
deadlock / time-lock check and every legal-set closure of every built-in model (default
instance, the partial-order reduction on where it acts, at most --max-states states)
gives the same JSON result as one process: verdict, message, states, edges, depth,
coverage and trace; only `seconds`, `threads` and `ranks` may differ, and `ranks` must be
N. One process runs with one thread, each rank with two. A property that does not run
distributed yet must say so in one line on stderr with exit 2. Three of them also on the
fingerprint store, and three on the compressed store (the same result but for the note
on the parts, which each rank's tree holds apart); and a suite (two models' entries),
where an entry that does not run
distributed is reported not run (incomplete) and the others are one process's.

usage: mpi_same.py TIOA_CHECK [--ranks 2 --ranks 4] [--max-states N]
Exit 77 (skipped) when mpirun is missing or tioa-check was built without MPI."""
import argparse
import concurrent.futures
import json
import os
import shutil
import subprocess
import sys

IGNORED = {"seconds", "threads", "ranks"}


def strip(x):
    if isinstance(x, dict):
        return {k: strip(v) for k, v in x.items() if k not in IGNORED}
    if isinstance(x, list):
        return [strip(v) for v in x]
    return x


def two_threads(command):
    """The command with two threads in each rank (one process runs with one)."""
    return [("2" if i > 0 and command[i - 1] == "-j" else c) for i, c in enumerate(command)]


def properties(report):
    return [p for m in report.get("models", [report]) for p in m["properties"]]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tioa")
    ap.add_argument("--ranks", type=int, action="append")
    ap.add_argument("--max-states", type=int, default=30000)
    args = ap.parse_args()
    ranks = args.ranks or [2]
    mpirun = shutil.which("mpirun")
    if not mpirun:
        print("SKIP: mpirun is not installed (apt-get install openmpi-bin libopenmpi-dev)")
        return 77
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    probe = subprocess.run([mpirun, "-np", "2", args.tioa, "list"], env=env,
                           capture_output=True, text=True, timeout=60)
    if "built without MPI" in probe.stderr:
        print("SKIP: tioa-check was built without MPI")
        return 77
    models = json.loads(subprocess.run([args.tioa, "list", "--json"], capture_output=True,
                                       text=True, check=True).stdout)["models"]

    def mpi(n, command):
        return subprocess.run([mpirun, "-np", str(n), args.tioa] + two_threads(command), env=env,
                              capture_output=True, text=True, timeout=300)

    # Each job gives its outcomes in order: ("same" | "refused" | "fail", text). A job is one
    # property (or explore, or suite) as one process and under each number of ranks.
    def property_job(model, prop):
        out = []
        command = ["check", model["name"], "--prop", prop["name"], "--json", "-j", "1",
                   "--max-states", str(args.max_states), "--max-seconds", "20"]
        one = subprocess.run([args.tioa] + command, capture_output=True, text=True, timeout=120)
        if one.returncode == 2:
            return out  # not a check of this instance (a usage error): nothing to compare
        mine = [p for p in properties(json.loads(one.stdout)) if p["name"] == prop["name"]]
        if not mine or mine[0].get("kind") not in ("invariant", "deadlock", "legal-set"):
            return out
        if mine[0]["verdict"] == "incomplete" and "time limit" in mine[0]["message"]:
            return out  # where a time limit stops is not deterministic
        for n in ranks:
            label = f"{model['name']} {prop['name']} -np {n}"
            run = mpi(n, command)
            if run.returncode == 2:
                lines = [l for l in run.stderr.splitlines() if "error:" in l]
                if len(lines) == 1 and "does not run distributed yet" in lines[0]:
                    out.append(("refused", f"{label}: {lines[0]}"))
                    continue
                out.append(("fail", f"{label}: exit 2: {run.stderr.strip()[:400]}"))
                continue
            if run.returncode != one.returncode:
                out.append(("fail", f"{label}: exit {run.returncode}, one process {one.returncode}"))
                continue
            theirs = [p for p in properties(json.loads(run.stdout)) if p["name"] == prop["name"]]
            if not theirs or theirs[0].get("ranks") != n:
                out.append(("fail", f"{label}: no result with ranks = {n}"))
                continue
            if strip(theirs[0]) != strip(mine[0]):
                diff = [k for k in mine[0] if strip(mine[0][k]) != strip(theirs[0].get(k))]
                out.append(("fail", f"{label}: differs in {diff}"))
                continue
            out.append(("same", f"{label}: {mine[0]['verdict']}, {mine[0]['states']} states, "
                                f"{mine[0]['edges']} edges"))
        return out

    # From every valuation (U(A)): a large start set, the limits met in level 0.
    def arbitrary_job(model):
        out = []
        command = ["explore", model["name"], "--from", "arbitrary", "--json", "-j", "1",
                   "--max-states", "20000", "--max-seconds", "20"]
        one = subprocess.run([args.tioa] + command, capture_output=True, text=True, timeout=120)
        if one.returncode == 2:
            return out
        mine = properties(json.loads(one.stdout))
        if any("time limit" in p["message"] for p in mine):
            return out
        for n in ranks:
            label = f"explore {model['name']} --from arbitrary -np {n}"
            run = mpi(n, command)
            lines = [l for l in run.stderr.splitlines() if "error:" in l]
            if run.returncode == 2 and len(lines) == 1 and "distributed yet" in lines[0]:
                out.append(("refused", f"{label}: {lines[0]}"))
                continue
            if run.returncode != one.returncode:
                out.append(("fail", f"{label}: exit {run.returncode}, one process {one.returncode}"))
                continue
            if strip(properties(json.loads(run.stdout))) != strip(mine):
                out.append(("fail", f"{label}: differs"))
                continue
            out.append(("same", f"{label}: " + ", ".join(
                f"{p['name']} {p['verdict']} {p['states']}" for p in mine)))
        return out

    # Another store: the fingerprint store (a state's owner is that of its fingerprint) or
    # the compressed store (each rank a tree of its own). One process's result, but for the
    # compressed store's note on the parts, which each rank's tree holds apart.
    def store_job(model, prop, store):
        out = []
        command = ["check", model, "--prop", prop, "--store", store, "--json", "-j", "1",
                   "--max-states", str(args.max_states), "--max-seconds", "20"]

        def without_parts_note(report):
            found = properties(report)
            for p in found:
                notes = p.get("notes", [])
                p["parts_noted"] = any(n.startswith("compressed store: ") for n in notes)
                p["notes"] = [n for n in notes if not n.startswith("compressed store: ")]
            return found

        one = subprocess.run([args.tioa] + command, capture_output=True, text=True, timeout=120)
        mine = without_parts_note(json.loads(one.stdout))
        for n in ranks:
            label = f"{model} {prop} --store {store} -np {n}"
            run = mpi(n, command)
            if run.returncode != one.returncode:
                out.append(("fail", f"{label}: exit {run.returncode}, one process {one.returncode}"))
                continue
            theirs = without_parts_note(json.loads(run.stdout))
            if strip(theirs) != strip(mine) or theirs[0].get("store") != store:
                out.append(("fail", f"{label}: differs"))
                continue
            out.append(("same", f"{label}: {mine[0]['verdict']}, {mine[0]['states']} states"))
        return out

    # The suite of two models: every entry that runs distributed as one process runs it,
    # every other one reported as not run (incomplete), and the suite goes on after it.
    def suite_job():
        out = []
        command = ["suite", "--model", "path-reservation", "--model", "token-ring", "--json",
                   "-j", "1"]
        one = json.loads(subprocess.run([args.tioa] + command, capture_output=True, text=True,
                                        timeout=300).stdout)["suite"]
        for n in ranks:
            theirs = json.loads(mpi(n, command).stdout)["suite"]
            if len(theirs) != len(one):
                out.append(("fail", f"suite -np {n}: {len(theirs)} entries, one process "
                                    f"{len(one)}"))
                continue
            not_run = 0
            for mine, other in zip(one, theirs):
                label = f"suite -np {n}: {mine['model']} {mine['property']}"
                if other["result"]["message"].startswith("not run: "):
                    not_run += 1
                    if other["result"]["verdict"] != "incomplete" or mine["result"].get(
                            "kind") in ("invariant", "deadlock", "legal-set"):
                        out.append(("fail", f"{label}: not run, or not incomplete"))
                elif strip(other["result"]) != strip(mine["result"]):
                    out.append(("fail", f"{label}: differs"))
            out.append(("same", f"suite -np {n}: {len(one) - not_run} entries as one process, "
                                f"{not_run} not run"))
        return out

    jobs = [lambda m=m, p=p: property_job(m, p) for m in models for p in m["properties"]]
    jobs += [lambda m=m: arbitrary_job(m) for m in models]
    jobs += [lambda m=m, p=p: store_job(m, p, "fingerprint")
             for m, p in [("fischer", "mutex"), ("vlayer-mc", "no-timelock"),
                          ("path-reservation", "mutual-exclusion")]]
    jobs += [lambda m=m, p=p: store_job(m, p, "compressed")
             for m, p in [("path-reservation", "no-collision"), ("fischer", "mutex"),
                          ("path-reservation", "integrity")]]
    jobs.append(suite_job)
    # Most of a run's time is mpirun starting and ending its ranks, not work: three jobs
    # at a time keep the two cores busy (the results do not depend on the timing: the
    # runs are bounded by states, and a time-limited one is not compared).
    failures, compared, refused = [], 0, 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=3) as pool:
        for outcomes in pool.map(lambda job: job(), jobs):
            for kind, text in outcomes:
                if kind == "fail":
                    failures.append(text)
                    continue
                compared += kind == "same"
                refused += kind == "refused"
                print(f"{kind} {text}", flush=True)
    print(f"{compared} runs the same as one process, {refused} refused in one line")
    for f in failures:
        print("FAIL", f)
    if compared == 0:
        print("FAIL nothing compared")
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
