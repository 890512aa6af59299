#!/usr/bin/env python3
"""Write a Unity .meta file, with a fresh random GUID, for every file and folder of the package and the
samples that lacks one. Unity ignores assets without a .meta in an immutable (git or registry) package;
the editor would write these itself, and there is no editor here. Folders ending in '~' and dot-files are
ignored by Unity and get none, but what is inside Samples~ does: the Package Manager copies a sample with its
.meta files into the project, so a scene that uses a sample's script keeps it across a re-import (without them
each import gives the scripts new GUIDs). Existing .meta files are never touched.

    python3 Tools/generate-meta.py            # from the repository root
    python3 Tools/generate-meta.py PATH...    # only under these paths (files or folders)
"""
import os
import sys
import uuid

ROOTS = ("Packages/com.kosmos.pseudohaptic", "Assets/Samples")
SAMPLES = "Samples~"  # ignored by Unity in the package, imported with its .meta files into a project

FOLDER = "fileFormatVersion: 2\nguid: {guid}\nfolderAsset: yes\nDefaultImporter:\n  externalObjects: {{}}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n"
SCRIPT = "fileFormatVersion: 2\nguid: {guid}\nMonoImporter:\n  externalObjects: {{}}\n  serializedVersion: 2\n  defaultReferences: []\n  executionOrder: 0\n  icon: {{instanceID: 0}}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n"
ASMDEF = "fileFormatVersion: 2\nguid: {guid}\nAssemblyDefinitionImporter:\n  externalObjects: {{}}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n"
TEXT = "fileFormatVersion: 2\nguid: {guid}\nTextScriptImporter:\n  externalObjects: {{}}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n"
PACKAGE = "fileFormatVersion: 2\nguid: {guid}\nPackageManifestImporter:\n  externalObjects: {{}}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n"
DEFAULT = "fileFormatVersion: 2\nguid: {guid}\nDefaultImporter:\n  externalObjects: {{}}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n"


def template(path, is_dir):
    if is_dir:
        return FOLDER
    name = os.path.basename(path)
    ext = os.path.splitext(name)[1].lower()
    if name == "package.json":
        return PACKAGE
    if ext == ".cs":
        return SCRIPT
    if ext in (".asmdef", ".asmref"):
        return ASMDEF
    if ext in (".md", ".json", ".txt", ".csv", ".xml", ".yaml", ".bytes"):
        return TEXT
    return DEFAULT


def write(path, is_dir):
    with open(path + ".meta", "w", newline="\n") as f:
        f.write(template(path, is_dir).format(guid=uuid.uuid4().hex))


def main():
    written = 0
    roots = sys.argv[1:] or ROOTS
    for root in roots:
        root = root.rstrip("/")
        # the folders above a given path need metas too, up to the package or samples root
        parent = os.path.dirname(root)
        while parent and any(parent.startswith(r) and parent != r for r in ROOTS):
            if not parent.endswith("~") and not os.path.exists(parent + ".meta"):
                write(parent, True)
                written += 1
            parent = os.path.dirname(parent)
        if os.path.isfile(root) or (os.path.isdir(root) and root not in ROOTS and not root.endswith("~")):
            if not os.path.exists(root + ".meta"):
                write(root, os.path.isdir(root))
                written += 1
        if not os.path.isdir(root):
            continue
        if not os.path.isdir(root):
            continue
        for dirpath, dirnames, filenames in os.walk(root):
            dirnames[:] = [d for d in dirnames if (d == SAMPLES or not d.endswith("~")) and not d.startswith(".")]
            entries = [(d, True) for d in dirnames if d != SAMPLES] + [(f, False) for f in filenames if not f.endswith(".meta") and not f.startswith(".")]
            for name, is_dir in entries:
                path = os.path.join(dirpath, name)
                if os.path.exists(path + ".meta"):
                    continue
                write(path, is_dir)
                written += 1
    print(f"wrote {written} .meta files")


if __name__ == "__main__":
    sys.exit(main())
