#!/usr/bin/env python3
"""`check mc-round --counterexample-out FILE` writes the smallest counterexample of a random
search as a round configuration; `check mc-round -p config=FILE` finds the same claim
violated on it, `round --config FILE` runs it, and the file holds what the report's witness
holds (issue 19).

usage: counterexample_reproduces.py TIOA_CHECK SCRATCH_DIR"""
import json
import subprocess
import sys
from pathlib import Path


def run(tool, *arguments, expect):
    done = subprocess.run([tool, *arguments], capture_output=True, text=True, check=False)
    if done.returncode != expect:
        sys.exit(f"{' '.join(arguments)}: exit {done.returncode}, expected {expect}\n"
                 f"{done.stderr}")
    return done


def main():
    tool, scratch = sys.argv[1], Path(sys.argv[2])
    scratch.mkdir(parents=True, exist_ok=True)
    for prop, params in (("lemma-6.4", "m=3,nbh=4,samples=20"),
                         ("lemma-6.4", "m=2,nbh=4,samples=40,seed=5,search_m=12")):
        out = scratch / f"{prop}.json"
        out.unlink(missing_ok=True)
        searched = run(tool, "check", "mc-round", "--prop", prop, "-p", params, "--json",
                       "--counterexample-out", str(out), expect=1)
        witness = next(w for w in json.loads(searched.stdout)["properties"][0]["witnesses"]
                       if w["role"] == "counterexample" and "config" in w)
        written = json.loads(out.read_text())
        if written != witness["config"]:
            sys.exit(f"{out} holds {written}, the report's witness {witness['config']}")
        again = run(tool, "check", "mc-round", "--prop", prop, "-p", f"config={out}", "--json",
                    expect=1)
        claims = json.loads(again.stdout)["properties"][0]["witnesses"]
        if not any(w["claim"] == witness["claim"] for w in claims):
            sys.exit(f"-p config={out}: claim {witness['claim']} not violated again")
        run(tool, "round", "--config", str(out), expect=0)
        print(f"ok   {prop} {params}: {witness['claim']} with {witness['robots']} robots "
              f"reproduces from {out.name}")
    # No counterexample: the file is not left behind.
    none = scratch / "none.json"
    none.write_text("stale")
    quiet = run(tool, "check", "mc-round", "--prop", "lemma-6.1", "-p", "m=2,nbh=4",
                "--counterexample-out", str(none), expect=0)
    if none.exists() or "not written" not in quiet.stderr:
        sys.exit("a run without a counterexample left the file, or did not say so")
    print("ok   no counterexample: no file")


if __name__ == "__main__":
    main()
