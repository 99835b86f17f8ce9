#!/usr/bin/env python3
"""Every kind of JSON document tioa-check writes, validated against docs/report.schema.json.

Usage: validate_reports.py TIOA_CHECK SCRATCH_DIR

Runs one invocation per interesting form of each document (a property that holds, one
violated with a trace, a lasso, a worst-case witness, an incomplete run, the fingerprint
store, explore from start and from arbitrary states, a model with a variant, mc-round's
witnesses of each kind, walks, a suite stopped at its time limit, an interrupted run, list,
round, simulate, trace files and their replay), checks its exit code, that it still shows
what it is here for, that it has a `version`, and validates it against the schema's
definition of its kind and then against the whole schema (exactly one kind matches).
Also checks that the schema is a valid draft 2020-12 schema and that it rejects a few
broken documents (so that a schema accepting anything does not pass).

Exit 0 when all is valid, 1 on the first failure (naming the invocation and the JSON path
of the error), 77 when the python3 module jsonschema is missing (CTest: skipped).
"""

import copy
import json
import os
import signal
import subprocess
import sys
import time

try:
    import jsonschema
    from jsonschema import Draft202012Validator
except ImportError:
    print("SKIPPED: the python3 module jsonschema is not installed (Debian: python3-jsonschema)")
    sys.exit(77)

HERE = os.path.dirname(os.path.abspath(__file__))
SCHEMA_PATH = os.path.join(HERE, "..", "..", "docs", "report.schema.json")
ROUND_CONFIG = os.path.join(HERE, "round", "corner.json")

# Documents the C++ does not yet write as the schema says: case name -> the one schema
# error expected. The document must fail with exactly that error and nothing else; when it
# passes, remove the entry.
KNOWN_GAPS = {}


class Failure(Exception):
    pass


class Case:
    """One invocation: its arguments, its exit code, and the documents it writes, each
    (kind in the schema's $defs, "stdout" or a file name in the scratch directory, what
    the document must show: (description, test) or None)."""

    def __init__(self, name, args, exit_code, documents, interrupt_after=None):
        self.name = name
        self.args = args
        self.exit_code = exit_code
        self.documents = documents
        self.interrupt_after = interrupt_after  # seconds before SIGINT, or None


def first_property(document):
    return document["properties"][0]


def has_witness_kinds(*kinds):
    def test(document):
        found = {w["kind"] for p in document["properties"] for w in p.get("witnesses", [])}
        return set(kinds) <= found

    return test


def cases():
    corner = ROUND_CONFIG
    given_start = "loc[1]=REQ, id=0, c[1]=0"
    given_invariant = "count(i in 1..2: loc[i] = CS) <= 1"
    return [
        Case("list", ["list", "--json"], 0,
             [("list_report", "stdout",
               ("a choice parameter", lambda d: any(
                   p["kind"] == "choice" for m in d["models"] for p in m["params"])))]),
        Case("check_holds", ["check", "fischer", "-p", "N=3", "--prop", "mutex", "--json"], 0,
             [("run_report", "stdout",
               ("holds, with a time note",
                lambda d: first_property(d)["verdict"] == "holds" and "time_note" in d))]),
        Case("check_violated",
             ["check", "fischer", "-p", "N=2,A=2,B=1", "--prop", "mutex", "--json"], 1,
             [("run_report", "stdout",
               ("an invariant counterexample with structured actions",
                lambda d: first_property(d)["trace"]["kind"] == "invariant"
                and first_property(d)["trace"]["steps"][1]["action"]["params"]))]),
        Case("check_lasso", ["check", "token-ring", "-p", "N=5,K=3", "--json"], 1,
             [("run_report", "stdout",
               ("a lasso", lambda d: any(
                   p.get("trace", {}).get("loop_start") is not None for p in d["properties"])))]),
        Case("check_worst_case",
             ["check", "token-ring", "-p", "N=5,K=4", "--prop", "convergence,transitivity",
              "--json"], 0,
             [("run_report", "stdout",
               ("a worst-case witness and worst_time",
                lambda d: first_property(d)["trace"]["kind"] == "worst-case"
                and "worst_time" in first_property(d)))]),
        Case("check_incomplete",
             ["check", "fischer", "--prop", "mutex", "--max-states", "10", "--json"], 3,
             [("run_report", "stdout",
               ("incomplete", lambda d: first_property(d)["verdict"] == "incomplete"))]),
        Case("check_fingerprint",
             ["check", "fischer", "-p", "N=3", "--store", "fingerprint", "--json"], 3,
             [("run_report", "stdout",
               ("the fingerprint store", lambda d: "omission_probability" in first_property(d)))]),
        Case("explore_start", ["explore", "fischer", "--from", "start", "--json"], 0,
             [("run_report", "stdout", ("from start", lambda d: d["from"] == "start"))]),
        Case("explore_arbitrary", ["explore", "fischer", "--from", "arbitrary", "--json"], 1,
             [("run_report", "stdout",
               ("a trace of no step", lambda d: first_property(d)["trace"]["length"] == 0))]),
        Case("check_variant_paper", ["check", "path-reservation", "--json"], 0,
             [("run_report", "stdout",
               ("the paper's variant", lambda d: d["variant"] == "paper"))]),
        Case("check_variant_broken",
             ["check", "path-reservation", "-p", "variant=release-before-reserve", "--json"], 1,
             [("run_report", "stdout",
               ("set-valued variables in a trace", lambda d: any(
                   isinstance(value, list) for value in
                   first_property(d)["trace"]["steps"][-1]["state"].values())))]),
        Case("check_variant_sampled",
             ["check", "vlayer-mc", "-p", "cols=1,window=closed,cn_repair=1", "--prop",
              "l1mc-closure", "--json"], 3,
             [("run_report", "stdout",
               ("a variant, sampled coverage of unknown size",
                lambda d: d["variant"] == "cn_repair=1"
                and first_property(d)["coverage"]["of"] is None))]),
        Case("mc_round_round",
             ["check", "mc-round", "--prop", "lemma-6.4", "-p", "m=2,nbh=4", "--json"], 1,
             [("run_report", "stdout", ("round witnesses", has_witness_kinds("round")))]),
        Case("mc_round_fixpoint",
             ["check", "mc-round", "--prop", "lemma-6.2", "-p", "family=given,m=2,n=2", "--json"],
             0, [("run_report", "stdout",
                  ("run-to-fixpoint witnesses", has_witness_kinds("run-to-fixpoint")))]),
        Case("mc_round_matrix",
             ["check", "mc-round", "--prop", "lemma-6.8", "-p", "family=given,m=2,n=2", "--json",
              "--trace-out", "mc_round.trace.json"], 0,
             [("run_report", "stdout",
               ("matrix and round-of-spacing witnesses",
                has_witness_kinds("matrix", "round-of-spacing"))),
              ("trace_file", "mc_round.trace.json",
               ("witnesses and no trace", lambda d: d["witnesses"] and not d["traces"]))]),
        Case("mc_round_positions",
             ["check", "mc-round", "--prop", "theorem-6.9", "-p", "family=given,m=2,n=2",
              "--json"], 1,
             [("run_report", "stdout", ("positions witnesses", has_witness_kinds("positions")))]),
        Case("walk", ["walk", "fischer", "--json", "--steps", "20"], 0,
             [("run_report", "stdout", ("a walk", lambda d: first_property(d)["kind"] == "walk"))]),
        Case("walk_broken",
             ["walk", "fischer", "-p", "N=2,A=2,B=1", "--steps", "100000", "--seed", "1", "--json",
              "--trace-out", "walk.trace.json"], 1,
             [("run_report", "stdout",
               ("a broken invariant", lambda d: first_property(d)["verdict"] == "violated")),
              ("trace_file", "walk.trace.json", ("from start", lambda d: d["from"] == "start"))]),
        Case("suite", ["suite", "--model", "token-ring", "--json"], 0,
             [("suite_report", "stdout",
               ("untimed entries", lambda d: d["suite"][0]["time_note"] is None))]),
        Case("suite_stopped",
             ["suite", "--model", "token-ring", "--max-seconds", "0.001", "--json"], 3,
             [("suite_report", "stdout", ("entries not run", lambda d: d["not_run"] > 0))]),
        Case("check_interrupted", ["check", "fischer", "-p", "N=10", "--por", "off", "--json"], 3,
             [("run_report", "stdout",
               ("interrupted", lambda d: d.get("interrupted") is True and d["not_run"]))],
             interrupt_after=1.0),
        Case("trace_out_invariant",
             ["check", "fischer", "-p", "N=2,A=2,B=1", "--prop", "mutex", "--json",
              "--trace-out", "mutex.trace.json"], 1,
             [("run_report", "stdout", None),
              ("trace_file", "mutex.trace.json",
               ("an invariant counterexample", lambda d: d["traces"][0]["kind"] == "invariant"))]),
        Case("replay_invariant", ["replay", "fischer", "mutex.trace.json", "--json"], 0,
             [("replay_report", "stdout", ("confirmed", lambda d: d["all_confirmed"]))]),
        Case("trace_out_lasso",
             ["check", "token-ring", "-p", "N=5,K=3", "--prop", "convergence",
              "--trace-out", "lasso.trace.json"], 1,
             [("trace_file", "lasso.trace.json",
               ("a lasso", lambda d: d["traces"][0]["loop_start"] is not None))]),
        Case("replay_lasso", ["replay", "token-ring", "lasso.trace.json", "--json"], 0,
             [("replay_report", "stdout", ("confirmed", lambda d: d["all_confirmed"]))]),
        Case("trace_out_worst_case",
             ["check", "token-ring", "-p", "N=4,K=4", "--trace-out", "worst.trace.json"], 0,
             [("trace_file", "worst.trace.json",
               ("last_time_outside", lambda d: any(
                   "last_time_outside" in t for t in d["traces"])))]),
        Case("replay_worst_case", ["replay", "token-ring", "worst.trace.json", "--json"], 0,
             [("replay_report", "stdout", ("confirmed", lambda d: d["all_confirmed"]))]),
        Case("trace_out_given",
             ["check", "fischer", "-p", "N=2,A=2,B=1", "--start", given_start,
              "--invariant", given_invariant, "--trace-out", "given.trace.json"], 1,
             [("trace_file", "given.trace.json",
               ("start and invariant", lambda d: "start" in d and "invariant" in d))]),
        Case("replay_given", ["replay", "fischer", "given.trace.json", "--json"], 0,
             [("replay_report", "stdout", ("confirmed", lambda d: d["all_confirmed"]))]),
        Case("trace_out_arbitrary",
             ["explore", "fischer", "--from", "arbitrary", "--trace-out", "arbitrary.trace.json"],
             1, [("trace_file", "arbitrary.trace.json",
                  ("from arbitrary", lambda d: d["from"] == "arbitrary"))]),
        Case("replay_arbitrary", ["replay", "fischer", "arbitrary.trace.json", "--json"], 0,
             [("replay_report", "stdout", ("confirmed", lambda d: d["all_confirmed"]))]),
        Case("trace_out_bound",
             ["check", "path-reservation", "-p", "scenario=convoy,capacity=1", "--prop",
              "no-collision", "--json", "--trace-out", "bound.trace.json"], 3,
             [("run_report", "stdout",
               ("incomplete at a full channel",
                lambda d: first_property(d)["verdict"] == "incomplete"
                and first_property(d)["trace"]["kind"] == "bound")),
              ("trace_file", "bound.trace.json",
               ("a bound witness", lambda d: d["traces"][0]["kind"] == "bound"))]),
        Case("replay_bound", ["replay", "path-reservation", "bound.trace.json", "--json"], 0,
             [("replay_report", "stdout", ("confirmed", lambda d: d["all_confirmed"]))]),
        Case("sweep_saved",
             ["sweep", "path-reservation", "-p", "scenario=random", "--over", "seed=1..2",
              "--prop", "mutual-exclusion,progress", "--save", "sweep", "--json"], 1,
             [("sweep_report", "stdout",
               ("a saved violated instance",
                lambda d: d["instances"] == 2 and any(r["saved"] for r in d["rows"])))]),
        Case("replay_tampered", ["replay", "fischer", "tampered.trace.json", "--json"], 1,
             [("replay_report", "stdout",
               ("does not replay", lambda d: not d["traces"][0]["replays"]))]),
        Case("round_one", ["round", "--config", corner, "--json"], 0,
             [("round_report", "stdout", ("one round", lambda d: d["T_stab"] is None))]),
        Case("round_fixpoint", ["round", "--config", corner, "--to-fixpoint", "--json"], 0,
             [("round_report", "stdout",
               ("to the fixed point", lambda d: d["T_stab"] is not None))]),
        Case("simulate_claim",
             ["simulate", "--m-from", "10", "--m-to", "11", "--curves", "c2,C3", "--robots", "1000",
              "--json"], 0,
             [("simulate_report", "stdout", ("the claim", lambda d: d["claim"] is not None))]),
        Case("simulate_no_claim",
             ["simulate", "--m-from", "10", "--m-to", "10", "--curves", "C1", "--robots", "100",
              "--json"], 0,
             [("simulate_report", "stdout", ("no claim", lambda d: d["claim"] is None))]),
    ]


def json_path(path):
    out = "$"
    for part in path:
        if isinstance(part, int):
            out += f"[{part}]"
        elif part.isidentifier():
            out += "." + part
        else:
            out += f"[{json.dumps(part)}]"
    return out


def pick(errors):
    """The error to report among `errors`: not an unevaluatedProperties one when there is
    another (it only follows from the other), and inside a oneOf / anyOf the branch that was
    meant: not one that fails on the value's type or on its "kind"."""
    errors = list(errors)
    error = max([e for e in errors if e.validator != "unevaluatedProperties"] or errors,
                key=jsonschema.exceptions.relevance)
    if not error.context:
        return error
    branches = {}
    for e in error.context:
        branches.setdefault(e.relative_schema_path[0], []).append(e)

    def off_target(branch):
        return any((e.validator in ("const", "enum") and list(e.relative_path) == ["kind"]) or
                   (e.validator == "type" and not e.relative_path) for e in branch)

    meant = [b for b in branches.values() if not off_target(b)] or list(branches.values())
    return pick(min(meant, key=len))


def describe(errors):
    error = pick(errors)
    schema_path = "/".join(str(p) for p in error.absolute_schema_path)
    return (f"at {json_path(error.absolute_path)}: {shorten(error.message)} "
            f"(schema {schema_path})")


def shorten(text, limit=300):
    return text if len(text) <= limit else text[:limit] + " ..."


def command_line(tool, case):
    return " ".join([os.path.basename(tool)] +
                    [a if a and " " not in a else json.dumps(a) for a in case.args])


def run(tool, case, scratch):
    if case.interrupt_after is None:
        done = subprocess.run([tool] + case.args, cwd=scratch, capture_output=True, timeout=120)
        return done.returncode, done.stdout, done.stderr
    process = subprocess.Popen([tool] + case.args, cwd=scratch, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE)
    time.sleep(case.interrupt_after)
    process.send_signal(signal.SIGINT)
    stdout, stderr = process.communicate(timeout=30)
    return process.returncode, stdout, stderr


def check_document(schema, kind, document, case_name):
    """Validates against the kind's definition (precise errors), then the whole schema."""
    if kind not in schema["$defs"]:
        raise Failure(f"the schema has no definition '{kind}'")
    one_kind = {key: value for key, value in schema.items() if key != "oneOf"}
    one_kind["$ref"] = "#/$defs/" + kind
    errors = list(Draft202012Validator(one_kind).iter_errors(document))
    gap = KNOWN_GAPS.get(case_name)
    if gap is not None:
        messages = [e.message for e in errors]
        if not messages:
            raise Failure(f"valid now: remove '{case_name}' from KNOWN_GAPS ({gap})")
        others = [e for e in errors if e.message != gap]
        if others:
            raise Failure(f"not a valid {kind} (besides the known gap): {describe(others)}")
        if len(messages) != 1:
            raise Failure(f"known gap {gap!r} expected once, got {len(messages)} times")
        return "known gap: " + gap
    if errors:
        raise Failure(f"not a valid {kind}: {describe(errors)}")
    if "version" not in document:
        raise Failure("no 'version'")
    matches = []
    for branch in schema["oneOf"]:
        if Draft202012Validator(dict(one_kind, **branch)).is_valid(document):
            matches.append(branch["$ref"].split("/")[-1])
    if matches != [kind]:
        raise Failure(f"the whole schema's oneOf matches {matches}, not exactly {kind}")
    whole = list(Draft202012Validator(schema).iter_errors(document))
    if whole:
        raise Failure("not valid under the whole schema: " + describe(whole))
    return None


def check_rejections(schema, valid):
    """Broken copies of valid documents that the schema must refuse."""
    validator = Draft202012Validator(schema)

    def broken(name, source, change):
        key = source if isinstance(source, tuple) else (source, "stdout")
        document = copy.deepcopy(valid[key])
        change(document)
        if validator.is_valid(document):
            raise Failure(f"the schema accepts a document with {name}")

    def step(document):
        return first_property(document)["trace"]["steps"][1]

    broken("no version", "check_violated", lambda d: d.pop("version"))
    broken("a verdict 'maybe'", "check_violated",
           lambda d: first_property(d).update(verdict="maybe"))
    broken("an unknown field in an action", "check_violated",
           lambda d: step(d)["action"].update(label="x"))
    broken("an action parameter as text", "check_violated",
           lambda d: step(d)["action"]["params"].update(p="1"))
    broken("a state value 1.5", "check_violated", lambda d: step(d)["state"].update(id=1.5))
    broken("an unknown field in a trace", "check_violated",
           lambda d: first_property(d)["trace"].update(extra=1))
    broken("por without reduced_states", "check_violated",
           lambda d: first_property(d).pop("reduced_states"))
    broken("the fingerprint store without omission_probability", "check_fingerprint",
           lambda d: first_property(d).pop("omission_probability"))
    broken("an unknown field in a witness", "mc_round_round",
           lambda d: first_property(d)["witnesses"][0].update(extra=1))
    broken("a round witness of kind matrix", "mc_round_round",
           lambda d: first_property(d)["witnesses"][0].update(kind="matrix"))
    broken("a trace file's trace without verdict", ("trace_out_invariant", "mutex.trace.json"),
           lambda d: d["traces"][0].pop("verdict"))
    broken("a trace file's witness without property", ("mc_round_matrix", "mc_round.trace.json"),
           lambda d: d["witnesses"][0].pop("property"))
    broken("a suite stopped without not_run", "suite_stopped", lambda d: d.pop("not_run"))


def tamper(scratch):
    """mutex.trace.json with c[1] of step 3 changed: a trace that does not replay."""
    with open(os.path.join(scratch, "mutex.trace.json")) as source:
        document = json.load(source)
    state = document["traces"][0]["steps"][3]["state"]
    state["c[1]"] = 1 - state["c[1]"]
    with open(os.path.join(scratch, "tampered.trace.json"), "w") as out:
        json.dump(document, out)


def main():
    if len(sys.argv) != 3:
        print(__doc__.strip().splitlines()[2])
        return 2
    tool, scratch = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    os.makedirs(scratch, exist_ok=True)
    with open(SCHEMA_PATH) as source:
        schema = json.load(source)
    try:
        Draft202012Validator.check_schema(schema)
    except jsonschema.exceptions.SchemaError as error:
        where = "/".join(str(p) for p in error.absolute_path)
        print("FAIL: docs/report.schema.json is not a valid draft 2020-12 schema: "
              f"{shorten(error.message)} at {where}")
        return 1

    started = time.monotonic()
    valid = {}  # (case name, "stdout" or file) -> the document, for check_rejections
    kinds = set()
    for case in cases():
        label = f"{case.name} ({command_line(tool, case)})"
        try:
            if case.name == "replay_tampered":
                tamper(scratch)
            for _, where, _ in case.documents:
                if where != "stdout" and os.path.exists(os.path.join(scratch, where)):
                    os.remove(os.path.join(scratch, where))
            case_started = time.monotonic()
            code, stdout, stderr = run(tool, case, scratch)
            seconds = time.monotonic() - case_started
            if code != case.exit_code:
                error_text = shorten(stderr.decode(errors="replace"))
                raise Failure(f"exit {code}, expected {case.exit_code}; stderr: {error_text}")
            notes = []
            for kind, where, shows in case.documents:
                if where == "stdout":
                    text = stdout.decode()
                else:
                    with open(os.path.join(scratch, where)) as source:
                        text = source.read()
                try:
                    document = json.loads(text)
                except ValueError as error:
                    raise Failure(f"{where} is not JSON: {error}")
                note = check_document(schema, kind, document, case.name)
                if note:
                    notes.append(note)
                if shows is not None:
                    what, test = shows
                    try:
                        shown = test(document)
                    except (KeyError, IndexError, TypeError):
                        shown = False
                    if not shown:
                        raise Failure(f"{where}: does not show what it is here for: {what}")
                valid[(case.name, where)] = document
                kinds.add(kind)
            aside = f"  ({'; '.join(notes)})" if notes else ""
            print(f"ok   {case.name:<24} {seconds:5.2f} s{aside}")
        except (Failure, subprocess.TimeoutExpired, OSError) as error:
            print(f"FAIL {label}: {error}")
            return 1
    try:
        check_rejections(schema, valid)
    except Failure as error:
        print(f"FAIL docs/report.schema.json: {error}")
        return 1
    gaps = f" except {len(KNOWN_GAPS)} known gaps (KNOWN_GAPS)" if KNOWN_GAPS else ""
    print(f"all documents valid{gaps}: {', '.join(sorted(kinds))}; "
          f"{time.monotonic() - started:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
