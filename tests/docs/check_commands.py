#!/usr/bin/env python3
"""Runs every command of a Markdown page and checks that it prints what the page shows.

Usage: check_commands.py PAGE BINDIR

In each ```sh block, a line starting with "$ " is a command; the lines after it, up to the
next "$ " line or the end of the block, are what it prints (stdout, then stderr). Commands
run with BINDIR first on PATH (so `tioa-check` is the one just built), one after another in
one fresh temporary directory (so a file one command writes is there for the next). Two
things may differ: trailing spaces, and the measured seconds ("seconds 0.000"), which are
compared as "seconds N". Exit 0 when every command prints what the page shows, else 1 with
a diff for each one that does not.
"""

import difflib
import os
import re
import subprocess
import sys
import tempfile

SECONDS = re.compile(r"seconds [0-9]+(\.[0-9]+)?")


def normalise(lines):
    return [SECONDS.sub("seconds N", line.rstrip()) for line in lines]


def commands(page):
    """(line number, command, expected output lines) for each "$ " line of a ```sh block."""
    found = []
    in_block = False
    current = None
    for number, line in enumerate(page.splitlines(), 1):
        if not in_block:
            in_block = line.strip() == "```sh"
            continue
        if line.strip() == "```":
            in_block = False
            current = None
            continue
        if line.startswith("$ "):
            current = (number, line[2:], [])
            found.append(current)
        elif current is not None:
            current[2].append(line)
    return found


def main():
    if len(sys.argv) != 3:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    page_path, bindir = sys.argv[1], sys.argv[2]
    with open(page_path, encoding="utf-8") as f:
        page = f.read()
    env = dict(os.environ, PATH=os.path.abspath(bindir) + os.pathsep + os.environ["PATH"])
    found = commands(page)
    if not found:
        print(f"{page_path}: no command in a ```sh block", file=sys.stderr)
        return 1
    failures = 0
    with tempfile.TemporaryDirectory() as work:
        for number, command, expected in found:
            run = subprocess.run(command, shell=True, cwd=work, env=env, capture_output=True,
                                 text=True, timeout=120)
            actual = normalise((run.stdout + run.stderr).splitlines())
            # A blank line closing the block's output is the page's layout, not output.
            while expected and not expected[-1].strip():
                expected.pop()
            while actual and not actual[-1]:
                actual.pop()
            if actual != normalise(expected):
                failures += 1
                print(f"{page_path}:{number}: $ {command}", file=sys.stderr)
                sys.stderr.writelines(line + "\n" for line in difflib.unified_diff(
                    normalise(expected), actual, "the page", "the command", lineterm=""))
    print(f"{len(found) - failures} of {len(found)} commands print what {page_path} shows")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
