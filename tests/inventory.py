#!/usr/bin/env python3
"""What a build's ctest runs: every entry with its tier, every GoogleTest case, and which
entry runs each case; with `compare`, whether a later build still runs everything an
earlier one ran.

Usage:
  inventory.py list BUILD [--assertions LOG]   one JSON document on stdout
  inventory.py compare BEFORE.json AFTER.json  JSON on stdout; exit 1 when something is lost
  inventory.py tiers BUILD                     exit 1, naming them, when entries do not carry
                                               exactly one tier label

`list` reads the entries from `ctest --show-only=json-v1` (no test runs) and the cases from
each GoogleTest binary's --gtest_list_tests. A case counts as run by an entry whose command
is its binary with a --gtest_filter that matches it, or with no filter (the whole binary).
LOG is what the test processes appended under VESICA_ASSERTION_LOG
(tests/support/AssertionCount.h): "<assertions> <command line>" a line; `list` sums it.

`compare` fails when a case of BEFORE is run by no entry of AFTER (or by one without a
tier label), or when an entry of BEFORE that is not a GoogleTest binary (a script, pytest)
has no entry of the same name in AFTER.
"""
import fnmatch
import json
import os
import subprocess
import sys

TIERS = ("unit", "acceptance", "fuzz", "install")


def ctest_entries(build):
    out = subprocess.run(["ctest", "--show-only=json-v1"], cwd=build, check=True,
                         capture_output=True, text=True).stdout
    entries = []
    for t in json.loads(out)["tests"]:
        props = {p["name"]: p["value"] for p in t.get("properties", [])}
        labels = props.get("LABELS", [])
        entries.append({"name": t["name"], "command": t.get("command", []),
                        "labels": labels if isinstance(labels, list) else [labels],
                        "disabled": bool(props.get("DISABLED", False))})
    return entries


def is_gtest_binary(path):
    """A built executable that lists GoogleTest cases (scripts and interpreters are not)."""
    if not path or not os.path.isfile(path) or not os.access(path, os.X_OK):
        return False
    with open(path, "rb") as f:
        if f.read(4) != b"\x7fELF":
            return False
    return b"gtest_list_tests" in open(path, "rb").read()


def gtest_cases(binary):
    """Suite.Case names, as --gtest_filter matches them (parameters and types stripped)."""
    out = subprocess.run([binary, "--gtest_list_tests"], check=True, capture_output=True,
                         text=True).stdout
    cases, suite = [], None
    for line in out.splitlines():
        if not line.strip() or line.startswith("Running main()"):
            continue
        if not line.startswith(" "):
            suite = line.split("#")[0].strip().rstrip(".")
        else:
            cases.append(f"{suite}.{line.split('#')[0].strip()}")
    return cases


def filter_matches(gtest_filter, name):
    """GoogleTest's --gtest_filter: POSITIVE[-NEGATIVE], each a ':'-list of globs."""
    positive, _, negative = gtest_filter.partition("-")
    pos = positive.split(":") if positive else ["*"]
    neg = negative.split(":") if negative else []
    return (any(fnmatch.fnmatchcase(name, p) for p in pos if p) and
            not any(fnmatch.fnmatchcase(name, n) for n in neg if n))


def entry_filter(entry):
    for arg in entry["command"][1:]:
        if arg.startswith("--gtest_filter="):
            return arg[len("--gtest_filter="):]
    return "*"


def tier_of(entry):
    tiers = [label for label in entry["labels"] if label in TIERS]
    return tiers[0] if len(tiers) == 1 else None


def assertion_total(log):
    total, processes = 0, 0
    with open(log) as f:
        for line in f:
            count = line.split(" ", 1)[0]
            if count.isdigit():
                total += int(count)
                processes += 1
    return total, processes


def list_build(build, log=None):
    entries = ctest_entries(build)
    binaries = sorted({e["command"][0] for e in entries
                       if e["command"] and is_gtest_binary(e["command"][0])})
    cases = {os.path.basename(b): gtest_cases(b) for b in binaries}
    runs = {}  # "binary:Suite.Case" -> entries that run it
    for e in entries:
        if e["disabled"] or not e["command"] or e["command"][0] not in binaries:
            continue
        binary = os.path.basename(e["command"][0])
        f = entry_filter(e)
        for case in cases[binary]:
            if filter_matches(f, case):
                runs.setdefault(f"{binary}:{case}", []).append(e["name"])
    by_tier = {}
    for e in entries:
        tier = tier_of(e) or "none"
        by_tier[tier] = by_tier.get(tier, 0) + 1
    doc = {
        "ctest_entries": len(entries),
        "ctest_entries_by_tier": by_tier,
        "gtest_binaries": len(binaries),
        "gtest_cases": sum(len(c) for c in cases.values()),
        "gtest_cases_run": len(runs),
        "gtest_cases_run_twice": sorted(k for k, v in runs.items() if len(v) > 1),
        "entries_without_one_tier": sorted(e["name"] for e in entries if not tier_of(e)),
        "entries": [{k: e[k] for k in ("name", "labels", "command")} for e in entries],
        "cases": cases,
        "runs": runs,
    }
    if log:
        total, processes = assertion_total(log) if os.path.exists(log) else (0, 0)
        doc["assertions"] = total
        doc["assertion_processes"] = processes
    return doc


def compare(before, after):
    tiers = {e["name"]: tier_of(e) for e in after["entries"]}
    lost_cases = []
    for binary, cases in before["cases"].items():
        for case in cases:
            key = f"{binary}:{case}"
            if key not in before["runs"]:
                continue  # it did not run before either (disabled)
            if not [n for n in after["runs"].get(key, []) if tiers.get(n)]:
                lost_cases.append(key)
    before_binaries = set(before["cases"])
    lost_entries = [e["name"] for e in before["entries"]
                    if not (e["command"] and os.path.basename(e["command"][0]) in before_binaries)
                    and not tiers.get(e["name"])]
    doc = {
        "before": {k: before.get(k) for k in ("ctest_entries", "gtest_cases_run", "assertions")},
        "after": {k: after.get(k) for k in ("ctest_entries", "gtest_cases_run", "assertions",
                                            "ctest_entries_by_tier")},
        "cases_no_longer_run": lost_cases,
        "other_entries_no_longer_run": lost_entries,
    }
    if before.get("assertions") is not None and after.get("assertions") is not None:
        doc["assertions_not_fewer"] = after["assertions"] >= before["assertions"]
    return doc, not lost_cases and not lost_entries


def main(argv):
    if len(argv) >= 2 and argv[0] == "list":
        log = argv[argv.index("--assertions") + 1] if "--assertions" in argv else None
        json.dump(list_build(os.path.abspath(argv[1]), log), sys.stdout, indent=1)
        print()
        return 0
    if len(argv) == 2 and argv[0] == "tiers":
        entries = ctest_entries(os.path.abspath(argv[1]))
        wrong = [e["name"] for e in entries if not tier_of(e)]
        for name in wrong:
            print(f"{name}: labels carry no tier or several of {', '.join(TIERS)}")
        print(f"{len(entries) - len(wrong)} of {len(entries)} ctest entries carry one tier")
        return 1 if wrong else 0
    if len(argv) == 3 and argv[0] == "compare":
        with open(argv[1]) as a, open(argv[2]) as b:
            doc, ok = compare(json.load(a), json.load(b))
        json.dump(doc, sys.stdout, indent=1)
        print()
        return 0 if ok else 1
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
