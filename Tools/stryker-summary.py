#!/usr/bin/env python3
"""Summarise a Stryker.NET JSON report (mutation-report.json) as quality.md's rows.

    python3 Tools/stryker-summary.py out/stryker/PIECE            # the piece's row (reads run.txt beside it)
    python3 Tools/stryker-summary.py REPORT.json --piece P --commit C --date D
    python3 Tools/stryker-summary.py out/stryker/PIECE --files      # also one row per file
    python3 Tools/stryker-summary.py out/stryker/PIECE --survivors  # list survivors and no-coverage mutants
    python3 Tools/stryker-summary.py out/stryker/PIECE --unchanged-at HEAD  # is the measured code still the code at HEAD?
    python3 Tools/stryker-summary.py --standing HEAD out/stryker/*         # what the reports say of HEAD, piece by piece and whole
    python3 Tools/stryker-summary.py out/stryker/PIECE --keep Tools/stryker-reports  # keep the run: Tools/stryker-reports/PIECE.json
    python3 Tools/stryker-summary.py --standing HEAD Tools/stryker-reports/*.json   # the standing from the kept runs

The argument is a report file or a folder holding one (out/stryker/PIECE from Tools/stryker-piece.sh, whose
run.txt gives the commit, start and end). Score = (killed + timeout) / (killed + timeout + survived + no
coverage), as Stryker computes it; compile errors and ignored mutants are left out, as Stryker does ("ignored"
counts those of the piece's files: `// Stryker disable` comments and Stryker's own filters, not the mutate filter). The row also
gives the score with timeouts counted as survivors (a lower bound; quality.md, "Timeouts").
--unchanged-at COMMIT compares the source the report holds of every file of the piece with that file at COMMIT (git show,
run from the repository): where none differs, the mutants are the same at COMMIT and the score is a lower bound there
(tests added since can only kill more); exit 1 when a file differs, naming it.
--standing COMMIT reads every report given and says what they measure of COMMIT: per piece, its newest run whose files
are all at COMMIT as measured (else its newest run, marked stale); per assembly (Core, Logic, Evaluation), every mutant of
every file at COMMIT with the status of the newest report that tested it on that very source, the files and mutants no
such report tested, and the score of what was tested. A mutant's source must match the whole file, not only its span.
A file whose code is the same and only its comments differ (`code_only`) counts as measured: Stryker mutates no comment,
and the line breaks stay, so every mutant keeps its place; a comment naming Stryker (`// Stryker disable`) counts as code.
--keep DIR writes the run as DIR/PIECE.json, small enough to commit (Stryker's report is tens of megabytes, and a folder
outside the repository does not outlive the machine): the run's meta (run.txt), and per file the SHA-256 of the source
measured and of its code alone (`code_only`), and every mutant's id, mutator, replacement, place and status, with the
line's code for survivors. Every mode reads such a file as it reads Stryker's report.
Python 3 standard library only. Exit 2 on a missing or unreadable report.
"""
import argparse
import glob
import hashlib
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


def measured(f):
    """The source a report measured of one file, with Unix line breaks (None in a kept run, which holds its hashes)."""
    return f["source"].replace("\r\n", "\n") if "source" in f else None


def sha256(text):
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def same_source(now, f):
    """Whether the file's source now (None: no such file) is, to the character, the source the report measured."""
    if now is None:
        return False
    return now == measured(f) if "source" in f else sha256(now) == f.get("sourceSha256")


def same_code_as(now, f):
    """Whether the file's code now is the code the report measured, comments aside (same_code)."""
    if now is None:
        return False
    if "source" in f:
        return same_code(now, measured(f))
    return sha256(now) == f.get("sourceSha256") or sha256(code_only(now)) == f.get("codeSha256")


def has_counted(f):
    """Whether a report's file has a mutant that counts in the score."""
    return any(m.get("status") in COUNTED for m in f.get("mutants", []))


def changed_at(files, commit, root):
    """The piece's files (those with a counted mutant) whose source at commit is not the source the report measured."""
    changed = []
    for name, f in sorted(files.items(), key=lambda kv: short(kv[0], root)):
        if not has_counted(f):
            continue
        shown = subprocess.run(["git", "show", "%s:%s" % (commit, repo_path(name))], capture_output=True)
        now = shown.stdout.decode("utf-8-sig") if shown.returncode == 0 else None
        if not same_code_as(now and now.replace("\r\n", "\n"), f):
            changed.append(short(name, root))
    return changed

def code_only(text):
    """C# source with its comments emptied (line breaks kept, and a block comment's last line as wide as it was, so every
    piece of code keeps its line and column): two sources with the same code_only differ only in comments, which Stryker does not mutate, so
    a report of one is a report of the other. Comments that speak to Stryker (`// Stryker disable …`) are kept."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i) or text.startswith("/*", i):
            end = text.find("\n", i) if c == "/" and text[i + 1] == "/" else text.find("*/", i + 2)
            end = n if end < 0 else (end if text[i + 1] == "/" else end + 2)
            comment = text[i:end]
            # a block comment's last line keeps its width, so that code after it on that line keeps its column
            tail = 0 if text[i + 1] == "/" else len(comment) - comment.rfind("\n") - 1
            out.append(comment if "Stryker" in comment else "\n" * comment.count("\n") + " " * tail)
            i = end
        elif c == '"' or c == "'":
            verbatim = c == '"' and i > 0 and text[i - 1] == "@" or i > 1 and text[i - 2:i] in ("@$", "$@")
            j = i + 1
            while j < n and text[j] != c:
                if text[j] == "\\" and not verbatim:
                    j += 1
                elif verbatim and text.startswith('""', j):
                    j += 1
                j += 1
            out.append(text[i:j + 1])
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def same_code(a, b):
    """Whether two sources (None: no such file) hold the same code, comments aside."""
    return a is not None and b is not None and (a == b or code_only(a) == code_only(b))


ASSEMBLIES = ("Core", "Logic", "Evaluation")
PACKAGE = "Packages/com.kosmos.pseudohaptic/Runtime/"


def git_text(commit, path):
    shown = subprocess.run(["git", "show", "%s:%s" % (commit, path)], capture_output=True)
    return shown.stdout.decode("utf-8-sig").replace("\r\n", "\n") if shown.returncode == 0 else None


def mutate_filtered(m):
    return m.get("status") == "Ignored" and "mutate filter" in (m.get("statusReason") or "")


def mutant_key(m):
    s, e = m["location"]["start"], m["location"]["end"]
    return (s["line"], s["column"], e["line"], e["column"], m.get("mutatorName"), m.get("replacement"))


def standing(commit, folders):
    """Per piece and per assembly: what the reports in folders measure of the code at commit."""
    runs = []
    for folder in folders:
        try:
            with open(find_report(folder), encoding="utf-8") as f:
                report = json.load(f)
        except FileNotFoundError as e:
            print("stryker-summary: skipped (a run unfinished or stopped): %s" % e, file=sys.stderr)
            continue
        except (OSError, ValueError) as e:
            print("stryker-summary: %s: %s" % (folder, e), file=sys.stderr)
            return 2
        meta = report.get("run") or read_meta(folder if os.path.isdir(folder) else os.path.dirname(folder))
        runs.append((meta.get("start", ""), meta, report))
    runs.sort(key=lambda r: r[0], reverse=True)  # newest first
    listed = subprocess.run(["git", "ls-tree", "-r", "--name-only", commit, PACKAGE], capture_output=True, text=True)
    if listed.returncode != 0:
        print("stryker-summary: git ls-tree %s failed: %s" % (commit, listed.stderr.strip()), file=sys.stderr)
        return 2
    sources = {p: git_text(commit, p) for p in listed.stdout.split() if p.endswith(".cs")}

    print("| piece | Stryker's score | killed | survived | timeouts | no coverage | commit | date (UTC) | at %s |" % commit)
    print("|---|---:|---:|---:|---:|---:|---|---|---|")
    seen = set()
    for start, meta, report in runs:
        piece = meta.get("piece", "?")
        if piece in seen:
            continue
        files = report.get("files", {})
        counted = [n for n in files if has_counted(files[n])]
        changed = [n for n in counted if not same_code_as(sources.get(repo_path(n)), files[n])]
        commented = [n for n in counted if n not in changed and not same_source(sources.get(repo_path(n)), files[n])]
        if changed:
            # an older run of the piece may still be of this code
            older = [r for r in runs if r[1].get("piece") == piece and r[0] < start]
            if any(all(same_code_as(sources.get(repo_path(n)), f)
                       for n, f in r[2].get("files", {}).items()
                       if has_counted(f)) for r in older):
                continue
        seen.add(piece)
        c = counts([m for f in files.values() for m in f.get("mutants", [])])
        where = "as measured" if not changed else "stale: " + ", ".join(
            "`%s`" % short(n, report.get("projectRoot", "")) for n in sorted(changed)) + " changed"
        if not changed and commented:
            where += " (comments changed in " + ", ".join(
                "`%s`" % short(n, report.get("projectRoot", "")) for n in sorted(commented)) + ")"
        print("| %s | %s | %d | %d | %d | %d | `%s` | %s %s | %s |" % (
            piece, pct(score(c)), c["Killed"], c["Survived"], c["Timeout"], c["NoCoverage"], meta.get("commit", "?"),
            start[:10], start[11:16], where))

    print()
    # files: the assembly's at commit; with a report: a report holds them as they are at commit (a file without mutants
    # counts here too); mutants: theirs, tested or not; tested: those a report of that source tested.
    print("| assembly at %s | files | with a report | mutants | tested | killed | survived | timeouts | no coverage "
          "| score of the tested |" % commit)
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    untested_files = {}
    for assembly in ASSEMBLIES:
        prefix = PACKAGE + assembly + "/"
        paths = sorted(p for p in sources if p.startswith(prefix))
        statuses, known, untested = {}, {}, []
        for path in paths:
            seen_as_is = False
            for start, meta, report in runs:
                for name, f in report.get("files", {}).items():
                    if repo_path(name) != path or not same_code_as(sources[path], f):
                        continue
                    seen_as_is = True
                    for m in f.get("mutants", []):
                        key = (path,) + mutant_key(m)
                        known[key] = True
                        if not mutate_filtered(m) and key not in statuses:
                            statuses[key] = m.get("status")
            if not seen_as_is:
                untested.append(path)
        c = counts([{"status": st} for st in statuses.values()])
        not_tested = sum(1 for k in known if k not in statuses)
        untested_files[assembly] = untested
        print("| %s | %d | %d | %d | %d | %d | %d | %d | %d | %s |" % (
            assembly, len(paths), len(paths) - len(untested), len(known), len(statuses), c["Killed"], c["Survived"], c["Timeout"],
            c["NoCoverage"], pct(score(c))))
    for assembly in ASSEMBLIES:
        if untested_files[assembly]:
            print()
            print("%s files no report measured as they are at %s: %s" % (assembly, commit, ", ".join(
                "`%s`" % p[len(PACKAGE) + len(assembly) + 1:] for p in untested_files[assembly])))
    return 0


def keep(report, meta, folder):
    """Writes the run as folder/PIECE.json: what --standing, --files, --survivors and --unchanged-at need of it, one mutant a
    line, so that a rerun's diff shows which mutants changed status."""
    files = {}
    for name, f in sorted(report.get("files", {}).items(), key=lambda kv: repo_path(kv[0])):
        src = measured(f)
        lines = src.split("\n") if src is not None else []
        mutants = []
        for m in sorted(f.get("mutants", []), key=mutant_key):
            if mutate_filtered(m):
                continue
            k = {"id": m.get("id"), "mutatorName": m.get("mutatorName"), "replacement": m.get("replacement"),
                 "location": m["location"], "status": m.get("status")}
            line = m["location"]["start"]["line"]
            if k["status"] in ("Survived", "NoCoverage"):
                k["code"] = m.get("code") or (lines[line - 1].strip() if 0 < line <= len(lines) else "")
            mutants.append(k)
        if not mutants:
            continue
        files[repo_path(name)] = {
            "sourceSha256": f.get("sourceSha256") or sha256(src),
            "codeSha256": f.get("codeSha256") or sha256(code_only(src)),
            "mutants": mutants}
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, meta.get("piece", "piece") + ".json")
    with open(path, "w", encoding="utf-8", newline="\n") as out:
        out.write('{"kept": 1, "run": %s,\n "files": {' % json.dumps(meta, sort_keys=True))
        for i, (name, f) in enumerate(files.items()):
            out.write('%s\n  %s: {"sourceSha256": "%s", "codeSha256": "%s", "mutants": [' % (
                "," if i else "", json.dumps(name), f["sourceSha256"], f["codeSha256"]))
            out.write(",".join("\n   " + json.dumps(m, sort_keys=True, ensure_ascii=False) for m in f["mutants"]))
            out.write("]}")
        out.write("}}\n")
    return path


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("report", nargs="+", help="mutation-report.json or a folder holding one (out/stryker/PIECE); "
                    "several only with --standing")
    ap.add_argument("--piece", help="piece name (default: run.txt's, else the folder's name)")
    ap.add_argument("--commit", help="commit measured (default: run.txt's)")
    ap.add_argument("--date", help="when (default: run.txt's start–end)")
    ap.add_argument("--files", action="store_true", help="also print one row per file")
    ap.add_argument("--survivors", action="store_true", help="list survived and no-coverage mutants")
    ap.add_argument("--unchanged-at", metavar="COMMIT", help="check that every file of the piece is at COMMIT as measured")
    ap.add_argument("--standing", metavar="COMMIT", help="what the reports given measure of COMMIT, per piece and assembly")
    ap.add_argument("--keep", metavar="DIR", help="write the run as DIR/PIECE.json, small enough to commit")
    a = ap.parse_args(argv)
    if a.standing:
        return standing(a.standing, a.report)
    if len(a.report) > 1:
        ap.error("several reports only with --standing")
    a.report = a.report[0]
    try:
        report_path = find_report(a.report)
        with open(report_path, encoding="utf-8") as f:
            report = json.load(f)
    except (OSError, ValueError) as e:
        print("stryker-summary: %s: %s" % (a.report, e), file=sys.stderr)
        return 2
    folder = a.report if os.path.isdir(a.report) else os.path.dirname(report_path)
    meta = report.get("run") or read_meta(folder)
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
                code = m.get("code") or (src[line - 1].strip() if 0 < line <= len(src) else "")
                print("%s:%d [%s] %s: %s -> %s" % (short(name, root), line, m["status"], m.get("mutatorName"),
                                                   code[:110], (m.get("replacement") or "").replace("\n", " ")[:110]))
    if a.keep:
        kept = keep(report, dict(meta, piece=piece, commit=commit), a.keep)
        print()
        print("kept as %s" % kept)
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
