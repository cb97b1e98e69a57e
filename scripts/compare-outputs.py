#!/usr/bin/python3
"""Compares two output trees of the same study runs, e.g. before and after a refactor:

    /usr/bin/python3 scripts/compare-outputs.py BEFORE AFTER

BEFORE and AFTER hold one folder per run (a driver's --out). For every CSV, the header and every
cell are compared exactly, except columns whose header names a timing or a memory figure; for
every summary.json, every error and figure (same exclusions), the size, step and time entries,
the file list and the notes. Prints one line per run (identical, or the differences) and exits 1
when any run differs. The refactors of issue 16 were checked with it (docs/architecture.md);
tests/tools/determinism_test.py compares 1 against 2 threads with it.
"""
import csv
import json
import math
import os
import sys

TIMING = ("wall", "second", "_per_s", "memory", "peak_mib", "run [s]", "setup", "assembly", "loop")


def timing(name):
    n = name.lower()
    return any(k in n for k in TIMING)


def compare_csv(before, after, rel):
    rb = list(csv.reader(open(before)))
    ra = list(csv.reader(open(after)))
    if not rb or not ra or rb[0] != ra[0]:
        return [f"{rel}: header differs"]
    if len(rb) != len(ra):
        return [f"{rel}: {len(rb)} rows -> {len(ra)}"]
    out = []
    for j, h in enumerate(rb[0]):
        if timing(h):
            continue
        for i in range(1, len(rb)):
            if j < len(rb[i]) and (j >= len(ra[i]) or rb[i][j] != ra[i][j]):
                out.append(f"{rel}: column '{h}' row {i}: {rb[i][j]} -> {ra[i][j] if j < len(ra[i]) else '(none)'}")
                break
    return out


def same(a, b):
    return a == b or (isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b))


def compare_summary(before, after):
    jb, ja = json.load(open(before)), json.load(open(after))
    out = []
    for section in ("errors", "figures"):
        for k, v in jb[section].items():
            if timing(k):
                continue
            if k not in ja[section]:
                out.append(f"summary {section}.{k}: missing")
            elif not same(v, ja[section][k]):
                out.append(f"summary {section}.{k}: {v} -> {ja[section][k]}")
        out += [f"summary {section}.{k}: new" for k in ja[section] if k not in jb[section]]
    for k in ("particles", "steps", "time_step", "simulated_time", "files", "notes"):
        if jb.get(k) != ja.get(k):
            out.append(f"summary {k}: {jb.get(k)} -> {ja.get(k)}")
    # The canonical case records, where both runs wrote them (before issue 16's case table none did).
    if "cases" in jb and "cases" in ja:
        if len(jb["cases"]) != len(ja["cases"]):
            out.append(f"summary cases: {len(jb['cases'])} -> {len(ja['cases'])}")
        for cb, ca in zip(jb["cases"], ja["cases"]):
            for k, v in cb.items():
                if timing(k):
                    continue
                if k not in ca or not same(v, ca[k]):
                    out.append(f"summary cases[{cb.get('case')}].{k}: {v} -> {ca.get(k)}")
    return out


def compare_run(bd, ad):
    problems = []
    for root, _, files in os.walk(bd):
        for f in files:
            rel = os.path.relpath(os.path.join(root, f), bd)
            ap = os.path.join(ad, rel)
            if not os.path.exists(ap):
                problems.append(f"{rel}: missing after")
            elif f.endswith(".csv"):
                problems += compare_csv(os.path.join(root, f), ap, rel)
            elif f == "summary.json":
                problems += compare_summary(os.path.join(root, f), ap)
    for root, _, files in os.walk(ad):
        for f in files:
            rel = os.path.relpath(os.path.join(root, f), ad)
            if not os.path.exists(os.path.join(bd, rel)):
                problems.append(f"{rel}: new after")
    return problems


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    before, after = argv[1], argv[2]
    differing = 0
    for run in sorted(os.listdir(before)):
        bd, ad = os.path.join(before, run), os.path.join(after, run)
        if not os.path.isdir(bd):
            continue
        problems = compare_run(bd, ad) if os.path.isdir(ad) else ["missing after"]
        differing += bool(problems)
        print(f"{run}: " + ("identical" if not problems else f"{len(problems)} differences"))
        for p in problems:
            print("   ", p)
    return 1 if differing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
