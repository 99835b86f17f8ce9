#!/usr/bin/env python3
"""`sweep --save` writes each violated instance as a file; checking that file with the
command the sweep prints gives the same verdicts and state counts (issue 16).

usage: sweep_reproduces.py TIOA_CHECK SCRATCH_DIR"""
import json
import shlex
import subprocess
import sys
from pathlib import Path


def main():
    tool, scratch = sys.argv[1], Path(sys.argv[2])
    scratch.mkdir(parents=True, exist_ok=True)
    saved = scratch / "saved"
    sweep = subprocess.run(
        [tool, "sweep", "path-reservation", "-p", "scenario=random,robots=3", "-p",
         "channels=fifo", "--over", "seed=1..6", "--save", str(saved), "--json", "-j", "2"],
        capture_output=True, text=True, check=False)
    if sweep.returncode != 1:
        sys.exit(f"sweep: exit {sweep.returncode}, expected 1 (something violated)\n{sweep.stderr}")
    report = json.loads(sweep.stdout)
    rows = [row for row in report["rows"] if row["saved"]]
    if not rows:
        sys.exit("no instance was saved")
    for row in rows:
        command = shlex.split(row["reproduce"])
        assert command[0] == "tioa-check" and "-p" in command, command
        again = subprocess.run([tool] + command[1:] + ["--json", "--trace", "none", "-j", "2"],
                               capture_output=True, text=True, check=False)
        if again.returncode != 1:
            sys.exit(f"seed {row['value']}: {row['reproduce']} exit {again.returncode}\n"
                     f"{again.stderr}")
        checked = {p["name"]: p for p in json.loads(again.stdout)["properties"]}
        for swept in row["properties"]:
            if swept["verdict"] != "violated":
                continue
            one = checked[swept["name"]]
            if (one["verdict"], one["states"]) != (swept["verdict"], swept["states"]):
                sys.exit(f"seed {row['value']} {swept['name']}: swept {swept['verdict']} "
                         f"{swept['states']}, the saved file {one['verdict']} {one['states']}")
        print(f"ok   seed {row['value']}: {Path(row['saved']).name} reproduces "
              f"{[p['name'] for p in row['properties'] if p['verdict'] == 'violated']}")


if __name__ == "__main__":
    main()
