#!/usr/bin/env python3
"""Line and branch coverage from coverlet's Cobertura files (.ci/run): the engine-free assemblies, and the Unity layer
(run under the test double), whose lines are also summed per folder, i.e. per asmdef of the package.

Usage: coverage.py FILE.cobertura.xml... Each test project writes one file; a line counts as covered when
any test project ran it, and a line's covered branches are the most any one project covered (a lower bound
of their union: Cobertura names no branch). Python 3 standard library only. Exits 0 whatever it finds."""
import re
import sys
import xml.etree.ElementTree as ET

ASSEMBLIES = ("Kosmos.PseudoHaptic.Core", "Kosmos.PseudoHaptic.Logic", "Kosmos.PseudoHaptic.Evaluation", "Kosmos.PseudoHaptic.Unity")
UNITY_FOLDERS = ("Runtime/Unity", "Runtime/Meta", "Runtime/Interaction", "Runtime/XRHands", "Editor", "Samples~")


def absolute(sources, filename):
    """The file's full path: under the first <source> root where it exists, else the first root."""
    import os
    for root in sources:
        path = os.path.normpath(os.path.join(root, filename))
        if os.path.exists(path):
            return path
    return os.path.normpath(os.path.join(sources[0], filename)) if sources else filename


def main(paths):
    lines = {}     # (assembly, file, line) -> hit
    branches = {}  # (assembly, file, line) -> (covered, total)
    for path in paths:
        try:
            root = ET.parse(path).getroot()
        except (ET.ParseError, OSError) as e:
            print(f"coverage: cannot read {path}: {e}")
            continue
        # Each report names files relative to its own <source> roots: join them, so that one file covered by several test
        # projects (the core is referenced by three) is one file here.
        sources = [src.text or "" for src in root.iter("source")]
        for package in root.iter("package"):
            name = package.get("name")
            if name not in ASSEMBLIES:
                continue
            for cls in package.iter("class"):
                filename = absolute(sources, cls.get("filename"))
                for line in cls.iter("line"):
                    key = (name, filename, int(line.get("number")))
                    lines[key] = lines.get(key, False) or int(line.get("hits", "0")) > 0
                    m = re.search(r"\((\d+)/(\d+)\)", line.get("condition-coverage", ""))
                    if line.get("branch") == "True" and m:
                        covered, total = int(m.group(1)), int(m.group(2))
                        old = branches.get(key, (0, total))
                        branches[key] = (max(old[0], covered), max(old[1], total))
    if not lines:
        print("coverage: no report for " + ", ".join(ASSEMBLIES))
        return
    for name in ASSEMBLIES:
        hit = sum(1 for k, v in lines.items() if k[0] == name and v)
        total = sum(1 for k in lines if k[0] == name)
        bc = sum(v[0] for k, v in branches.items() if k[0] == name)
        bt = sum(v[1] for k, v in branches.items() if k[0] == name)
        pct = lambda a, b: f"{100.0 * a / b:.1f} %" if b else "n/a"
        print(f"coverage {name}: lines {pct(hit, total)} ({hit}/{total}), branches {pct(bc, bt)} ({bc}/{bt})")
    for folder in UNITY_FOLDERS:
        keys = [k for k in lines if k[0] == "Kosmos.PseudoHaptic.Unity" and ("/" + k[1].replace("\\", "/")).find("/" + folder + "/") >= 0]
        if keys:
            hit = sum(1 for k in keys if lines[k])
            print(f"coverage   {folder}: lines {100.0 * hit / len(keys):.1f} % ({hit}/{len(keys)})")


if __name__ == "__main__":
    main(sys.argv[1:])
