#!/usr/bin/env python3
"""Compares the rows of two `sextant reproduce` result folders, timings aside.

    scripts/compare_runs.py BEFORE AFTER

Rows are matched by experiment and run key. Every value and series must be equal, except the
measured times (keys naming seconds, milliseconds or time), which differ from run to run. Exits 1
and lists the first differences when anything else differs, then how many rows of each experiment
are missing on either side or differ (the list stops at 40; the counts do not). Used to show that a
refactoring left the quick profile's results unchanged.
"""
import json
import re
import sys
from collections import Counter
from pathlib import Path

# Measured times, and ratios of measured times.
TIMING = re.compile(r"(^|_)(seconds|ms|time|s)(_|$)|^registration_extra$")


def rows(folder):
    found = {}
    for path in sorted(Path(folder).glob("*/runs.jsonl")):
        for line in path.read_text().splitlines():
            if line.strip():
                row = json.loads(line)
                found[(row["experiment"], row["key"])] = row
    return found


def without_timings(value):
    if isinstance(value, dict):
        return {k: without_timings(v) for k, v in value.items() if not TIMING.search(k)}
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    return value


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    before, after = rows(sys.argv[1]), rows(sys.argv[2])
    problems = [f"only in {sys.argv[1]}: {k}" for k in sorted(before.keys() - after.keys())]
    problems += [f"only in {sys.argv[2]}: {k}" for k in sorted(after.keys() - before.keys())]
    per_experiment = Counter()  # (experiment, what) → rows
    for key in before.keys() - after.keys():
        per_experiment[(key[0], f"only in {sys.argv[1]}")] += 1
    for key in after.keys() - before.keys():
        per_experiment[(key[0], f"only in {sys.argv[2]}")] += 1
    for key in sorted(before.keys() & after.keys()):
        a, b = without_timings(before[key]), without_timings(after[key])
        if a != b:
            fields = sorted(f for f in set(a) | set(b) if a.get(f) != b.get(f))
            detail = fields
            if fields == ["values"]:
                detail = sorted(v for v in set(a["values"]) | set(b["values"])
                                if a["values"].get(v) != b["values"].get(v))
            problems.append(f"{key}: differs in {detail}")
            per_experiment[(key[0], "differ")] += 1
    for p in problems[:40]:
        print(p)
    for (experiment, what), n in sorted(per_experiment.items()):
        print(f"{experiment}: {n} rows {what}")
    print(f"{len(before)} rows before, {len(after)} after, {len(problems)} differences")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
