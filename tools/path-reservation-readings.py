#!/usr/bin/env python3
"""The table of readings of seed 004 (issue 16): every reading (msg_rule x channels x reach
x disk x variant) on every built-in scenario, the verdict of each property, as a Markdown
table for models/path_reservation/README.md.

usage: tools/path-reservation-readings.py [TIOA_CHECK] [--scenarios a,b,...] [--threads N]
                                         [--where name=value,...] [--no-header]

Each cell is five letters, one a property, in the order mutual-exclusion, integrity,
no-collision, progress, progress-unless-detected: h holds, V violated, ? incomplete;
"refused" when the reading refuses the scenario (disk=open and a zone on the disk's edge).
"""
import argparse
import itertools
import json
import subprocess
import sys

PROPERTIES = ["mutual-exclusion", "integrity", "no-collision", "progress",
              "progress-unless-detected"]
LETTER = {"holds": "h", "violated": "V", "incomplete": "?"}
READINGS = [("variant", ["paper", "round-tags"]),
            ("msg_rule", ["discover-zone", "any-zone"]),
            ("channels", ["any", "fifo"]),
            ("reach", ["open", "closed"]),
            ("disk", ["closed", "open"])]


def cell(tool, scenario, reading, threads):
    params = ",".join(f"{k}={v}" for k, v in reading)
    run = subprocess.run([tool, "check", "path-reservation", "-p", f"scenario={scenario}",
                          "-p", params, "--json", "--trace", "none", "-j", str(threads)],
                         capture_output=True, text=True, check=False)
    if run.returncode == 2:
        if "leaves the open disk" in run.stderr:
            return "refused"
        sys.exit(f"{scenario} {params}: {run.stderr.strip()}")
    verdicts = {p["name"]: p["verdict"] for p in json.loads(run.stdout)["properties"]}
    return "".join(LETTER[verdicts[name]] for name in PROPERTIES)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("tool", nargs="?", default="build/cli/tioa-check")
    parser.add_argument("--scenarios",
                        default="crossing,head-on,convoy,cycle,late-joiner,range-edge,pinwheel,"
                                "convoy-3x2")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--where", default="",
                        help="only the readings with these values; a parameter outside the "
                             "table (delivery=anywhere) is set on every run")
    parser.add_argument("--no-header", action="store_true")
    args = parser.parse_args()
    scenarios = args.scenarios.split(",")
    where = dict(item.split("=") for item in args.where.split(",") if item)
    if not args.no_header:
        print("| variant | msg_rule | channels | reach | disk | " + " | ".join(scenarios) + " |")
        print("| --- " * (5 + len(scenarios)) + "|")
    for values in itertools.product(*[choices for _, choices in READINGS]):
        reading = list(zip([name for name, _ in READINGS], values))
        if any(k in dict(reading) and dict(reading)[k] != v for k, v in where.items()):
            continue
        reading += [(k, v) for k, v in where.items() if k not in dict(reading)]
        cells = [cell(args.tool, s, reading, args.threads) for s in scenarios]
        print("| " + " | ".join(values) + " | " + " | ".join(f"`{c}`" if c != "refused" else c
                                                              for c in cells) + " |",
              flush=True)


if __name__ == "__main__":
    main()
