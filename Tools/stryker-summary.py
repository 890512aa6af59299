#!/usr/bin/env python3
"""Summarise a Stryker.NET JSON report (mutation-report.json) as quality.md's rows.

    python3 Tools/stryker-summary.py out/stryker/PIECE            # the piece's row (reads run.txt beside it)
    python3 Tools/stryker-summary.py REPORT.json --piece P --commit C --date D
    python3 Tools/stryker-summary.py out/stryker/PIECE --files      # also one row per file
    python3 Tools/stryker-summary.py out/stryker/PIECE --survivors  # list survivors and no-coverage mutants
    python3 Tools/stryker-summary.py out/stryker/PIECE --unchanged-at HEAD  # is the measured code still the code at HEAD?

The argument is a report file or a folder holding one (out/stryker/PIECE from Tools/stryker-piece.sh, whose
run.txt gives the commit, start and end). Score = (killed + timeout) / (killed + timeout + survived + no
coverage), as Stryker computes it; compile errors and ignored mutants are left out, as Stryker does ("ignored"
counts those of the piece's files: `// Stryker disable` comments and Stryker's own filters, not the mutate filter). The row also
gives the score with timeouts counted as survivors (a lower bound; quality.md, "Timeouts").
--unchanged-at COMMIT compares the source the report holds of every file of the piece with that file at COMMIT (git show,
run from the repository): where none differs, the mutants are the same at COMMIT and the score is a lower bound there
(tests added since can only kill more); exit 1 when a file differs, naming it.
Python 3 standard library only. Exit 2 on a missing or unreadable report.
"""
import argparse
import glob
import json
import os
import subprocess
import sys

COUNTED = ("Killed", "Timeout", "Survived", "NoCoverage")


def find_report(path):
    if os.path.isfile(path):
        return path
    hits = sorted(glob.glob(os.path.join(path, "**", "mutation-report.json"), recursive=True),
                  key=os.path.getmtime)
    if not hits:
        raise FileNotFoundError("no mutation-report.json under " + path)
    return hits[-1]


def read_meta(folder):
    meta = {}
    p = os.path.join(folder, "run.txt")
    if os.path.isfile(p):
        with open(p, encoding="utf-8") as f:
            for line in f:
                key, _, value = line.partition(":")
                meta[key.strip()] = value.strip()
    return meta


def counts(mutants):
    c = {s: 0 for s in COUNTED + ("CompileError", "Ignored", "Other")}
    for m in mutants:
        s = m.get("status")
        if s == "Ignored" and "mutate filter" in (m.get("statusReason") or ""):
            continue  # outside the piece (-m), not a mutant of it
        c[s if s in c else "Other"] += 1
    return c


def score(c, timeouts_survive=False):
    detected = c["Killed"] + (0 if timeouts_survive else c["Timeout"])
    total = c["Killed"] + c["Timeout"] + c["Survived"] + c["NoCoverage"]
    return None if total == 0 else 100.0 * detected / total


def pct(x):
    return "–" if x is None else "%.2f %%" % x


def short(path, root):
    p = path.replace("\\", "/")
    for marker in ("/Runtime/Core/", "/Runtime/Logic/", "/Runtime/Evaluation/"):
        if marker in p:
            return p.split(marker, 1)[1]
    return os.path.relpath(p, root) if root else p


def repo_path(path):
    """The file's path in the repository: from Packages/ on."""
    p = path.replace("\\", "/")
    at = p.find("Packages/com.kosmos.pseudohaptic/")
    return p[at:] if at >= 0 else p


def changed_at(files, commit, root):
    """The piece's files (those with a counted mutant) whose source at commit is not the source the report measured."""
    changed = []
    for name, f in sorted(files.items(), key=lambda kv: short(kv[0], root)):
        if not any(m.get("status") in COUNTED for m in f.get("mutants", [])):
            continue
        shown = subprocess.run(["git", "show", "%s:%s" % (commit, repo_path(name))], capture_output=True)
        now = shown.stdout.decode("utf-8-sig") if shown.returncode == 0 else None
        if now is None or now.replace("\r\n", "\n") != f.get("source", "").replace("\r\n", "\n"):
            changed.append(short(name, root))
    return changed


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("report", help="mutation-report.json or a folder holding one (out/stryker/PIECE)")
    ap.add_argument("--piece", help="piece name (default: run.txt's, else the folder's name)")
    ap.add_argument("--commit", help="commit measured (default: run.txt's)")
    ap.add_argument("--date", help="when (default: run.txt's start–end)")
    ap.add_argument("--files", action="store_true", help="also print one row per file")
    ap.add_argument("--survivors", action="store_true", help="list survived and no-coverage mutants")
    ap.add_argument("--unchanged-at", metavar="COMMIT", help="check that every file of the piece is at COMMIT as measured")
    a = ap.parse_args(argv)
    try:
        report_path = find_report(a.report)
        with open(report_path, encoding="utf-8") as f:
            report = json.load(f)
    except (OSError, ValueError) as e:
        print("stryker-summary: %s: %s" % (a.report, e), file=sys.stderr)
        return 2
    folder = a.report if os.path.isdir(a.report) else os.path.dirname(report_path)
    meta = read_meta(folder)
    piece = a.piece or meta.get("piece") or os.path.basename(os.path.normpath(folder))
    commit = a.commit or meta.get("commit", "?")
    if a.date:
        date = a.date
    elif "start" in meta:
        start, end = meta["start"], meta.get("end", "unfinished")
        date = "%s %s–%s" % (start[:10], start[11:16], end[11:16] if len(end) > 16 else end)
    else:
        date = "?"
    root = report.get("projectRoot", "")
    files = report.get("files", {})
    allm = [m for f in files.values() for m in f.get("mutants", [])]
    c = counts(allm)
    print("| piece | Stryker's score | timeouts as survivors | killed | survived | timeouts | no coverage "
          "| compile errors | ignored | commit | date (UTC) |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---|")
    print("| %s | **%s** | %s | %d | %d | %d | %d | %d | %d | `%s` | %s |" % (
        piece, pct(score(c)), pct(score(c, True)), c["Killed"], c["Survived"], c["Timeout"], c["NoCoverage"],
        c["CompileError"], c["Ignored"], commit, date))
    if a.files:
        print()
        print("| file | score | killed | survived | timeouts | no coverage |")
        print("|---|---:|---:|---:|---:|---:|")
        for name in sorted(files, key=lambda n: short(n, root)):
            fc = counts(files[name].get("mutants", []))
            if sum(fc[s] for s in COUNTED) == 0:
                continue
            print("| `%s` | %s | %d | %d | %d | %d |" % (short(name, root), pct(score(fc)), fc["Killed"],
                                                          fc["Survived"], fc["Timeout"], fc["NoCoverage"]))
    if a.survivors:
        print()
        for name in sorted(files, key=lambda n: short(n, root)):
            src = files[name].get("source", "").splitlines()
            for m in sorted(files[name].get("mutants", []), key=lambda m: m["location"]["start"]["line"]):
                if m.get("status") not in ("Survived", "NoCoverage"):
                    continue
                line = m["location"]["start"]["line"]
                code = src[line - 1].strip() if 0 < line <= len(src) else ""
                print("%s:%d [%s] %s: %s -> %s" % (short(name, root), line, m["status"], m.get("mutatorName"),
                                                   code[:110], (m.get("replacement") or "").replace("\n", " ")[:110]))
    if a.unchanged_at:
        changed = changed_at(files, a.unchanged_at, root)
        print()
        if changed:
            print("changed at %s since the run: %s" % (a.unchanged_at, ", ".join("`%s`" % n for n in changed)))
            return 1
        print("every file of %s is at %s as measured at %s" % (piece, a.unchanged_at, commit))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
