#!/usr/bin/env python3
"""Runs every command of a Markdown page and checks that it prints what the page shows.

Usage: check_commands.py PAGE BINDIR [--source FILE]

In each ```sh block, a line starting with "$ " is a command; the lines after it, up to the
next "$ " line or the end of the block, are what it prints (stdout, then stderr). Commands
run with BINDIR first on PATH (so `tioa-check` is the one just built), one after another in
one fresh temporary directory (so a file one command writes is there for the next). Two
things may differ: trailing spaces, and the measured seconds, which are compared as N: in
a report ("seconds 0.000"), in the last column of a suite row ("holds  holds ... 0.000")
and in the suite's summary ("0.01 s: OK").

With --source FILE, each ```cpp block of the page must also appear in FILE, line for line
(leading and trailing spaces aside), so that the code the page shows is the code that runs.
Exit 0 when every command prints what the page shows (and every snippet is in FILE), else
1 with a diff for each one that does not.
"""

import difflib
import os
import re
import subprocess
import sys
import tempfile

SECONDS = re.compile(r"seconds [0-9]+(\.[0-9]+)?")
VERDICT = r"(?:holds|violated|incomplete)"
SUITE_ROW = re.compile(rf"^(.* {VERDICT} +{VERDICT} .*?) +[0-9]+\.[0-9]{{3}}(   <- NOT AS EXPECTED)?$")
SUITE_SUMMARY = re.compile(r"(not as expected), [0-9]+\.[0-9]+ s: (OK|FAILED|INCOMPLETE)$")


def normalise_line(line):
    line = SECONDS.sub("seconds N", line.rstrip())
    line = SUITE_ROW.sub(lambda m: m.group(1) + "  N" + (m.group(2) or ""), line)
    return SUITE_SUMMARY.sub(r"\1, N s: \2", line)


def normalise(lines):
    return [normalise_line(line) for line in lines]


def snippets(page, fence):
    """(line number, lines) for each block opened by `fence` ("```cpp")."""
    found = []
    current = None
    for number, line in enumerate(page.splitlines(), 1):
        if current is None:
            if line.strip() == fence:
                current = (number, [])
                found.append(current)
        elif line.strip() == "```":
            current = None
        else:
            current[1].append(line.strip())
    return found


def missing_snippets(page_path, page, source_path):
    """The number of ```cpp blocks of the page that are not in the source, each reported."""
    with open(source_path, encoding="utf-8") as f:
        source = [line.strip() for line in f.read().splitlines()]
    missing = 0
    for number, lines in snippets(page, "```cpp"):
        lines = [line for line in lines if line]
        body = [line for line in source if line]
        if not any(body[i:i + len(lines)] == lines for i in range(len(body) - len(lines) + 1)):
            missing += 1
            print(f"{page_path}:{number}: this ```cpp block is not in {source_path}",
                  file=sys.stderr)
    return missing


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
    args = sys.argv[1:]
    source_path = None
    if len(args) == 4 and args[2] == "--source":
        source_path = args[3]
        args = args[:2]
    if len(args) != 2:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    page_path, bindir = args
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
    if source_path is not None:
        failures += missing_snippets(page_path, page, source_path)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
