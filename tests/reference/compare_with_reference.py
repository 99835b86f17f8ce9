#!/usr/bin/env python3
"""Cross-checks tioa-check against the independent brute-force enumerator.

tools/reference/peer_models.py explores the two peer models of
../shared/peer-models.md with plain Python sets and dictionaries, sharing no code
with the checker. This script runs it, runs `tioa-check check ... --json` on the
same instances, and compares state counts, edge counts, legal-set sizes,
worst-case stabilisation steps and shortest counterexample lengths.

Usage: compare_with_reference.py TIOA_CHECK   (exit 0 when everything agrees)
"""
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REFERENCE = os.path.join(HERE, "..", "..", "tools", "reference", "peer_models.py")


def run_checker(binary, model, params, props):
    command = [binary, "check", model, "--json", "--threads", "2",
               "--param", ",".join(f"{k}={v}" for k, v in params.items()),
               "--prop", ",".join(props)]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode not in (0, 1):
        raise SystemExit(f"{' '.join(command)} exited {done.returncode}: {done.stderr}")
    return {p["name"]: p for p in json.loads(done.stdout)["properties"]}


def main():
    binary = sys.argv[1]
    reference = json.loads(subprocess.run(
        [sys.executable, REFERENCE, "--skip-large"], capture_output=True, text=True,
        check=True).stdout)
    mismatches = []
    compared = 0

    def expect(what, ours, theirs):
        nonlocal compared
        compared += 1
        if ours != theirs:
            mismatches.append(f"{what}: tioa-check {ours}, reference {theirs}")

    for ring in reference["dijkstra"]:
        n, k = ring["N"], ring["K"]
        name = f"token-ring N={n} K={k}"
        got = run_checker(binary, "token-ring", {"N": n, "K": k},
                          ["some-privileged", "legal-closure", "convergence"])
        expect(f"{name} states", got["some-privileged"]["states"], ring["states"])
        expect(f"{name} edges", got["some-privileged"]["edges"], ring["edges"])
        expect(f"{name} |L|", got["legal-closure"]["states"], ring["L_size"])
        expect(f"{name} L closed", got["legal-closure"]["verdict"] == "holds", ring["L_closed"])
        conv = got["convergence"]
        expect(f"{name} converges", conv["verdict"] == "holds", ring["converges"])
        if ring["converges"]:
            expect(f"{name} worst steps", conv["worst_time"], ring["worst_steps"])

    for fischer in reference["fischer"]:
        params = {"N": fischer["N"], "A": fischer["A"], "B": fischer["B"]}
        name = "fischer " + " ".join(f"{k}={v}" for k, v in params.items())
        got = run_checker(binary, "fischer", params, ["no-timelock", "mutex"])
        expect(f"{name} states", got["no-timelock"]["states"], fischer["states"])
        expect(f"{name} edges", got["no-timelock"]["edges"], fischer["edges"])
        expect(f"{name} time-locks", got["no-timelock"]["verdict"] == "holds",
               fischer["deadlocks"] == 0)
        expect(f"{name} mutex", got["mutex"]["verdict"] == "holds", fischer["mutex_holds"])
        if not fischer["mutex_holds"]:
            expect(f"{name} shortest counterexample", got["mutex"]["trace"]["length"],
                   fischer["shortest_cex_length"])

    for line in mismatches:
        print("MISMATCH", line)
    print(f"{compared - len(mismatches)} passed, {len(mismatches)} failed")
    return 1 if mismatches else 0


if __name__ == "__main__":
    sys.exit(main())
