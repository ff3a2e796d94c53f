#!/usr/bin/env python3
"""Checks that CONTRIBUTING.md matches the tree: its "Layout" block and its list of fuzz targets.

Usage: check_contributing.py [REPOSITORY_ROOT]

Layout block: a line that starts with a path ending in '/' names a folder, which must exist; the
file names on its lines (with * as a wildcard) must each match a file in that folder. Every
top-level folder, every folder under src/, bench/ and tools/, every public header and every
document in docs/ must be named. Fuzzers: the fuzz_* names after "Targets:" must be exactly the
fuzz/fuzz_*.c files."""
import fnmatch
import os
import re
import sys

FILE_RE = re.compile(r"[\w*.-]+\.(?:h|c|md|in|sh|inc|py|json|svg|cmake)\b")
EXTENSIONS = (".h", ".c", ".md", ".in", ".sh", ".inc", ".py", ".json", ".svg", ".cmake")


def layout_entries(text):
    m = re.search(r"^## Layout\s*\n+```\n(.*?)```", text, flags=re.S | re.M)
    if not m:
        return None
    entries = []  # (folder, text of its lines)
    for line in m.group(1).split("\n"):
        first = re.match(r"^(\S+/)\s*(.*)$", line)
        if first:
            entries.append([first.group(1), first.group(2)])
        elif entries and line.strip():
            entries[-1][1] += " " + line.strip()
    return entries


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    text = open(os.path.join(root, "CONTRIBUTING.md"), encoding="utf-8").read()
    errors = []
    entries = layout_entries(text)
    if entries is None:
        print("check_contributing: no ```-block after '## Layout'")
        return 1
    named_folders = set()
    named_text = {}
    for folder, body in entries:
        path = os.path.join(root, folder)
        if not os.path.isdir(path):
            errors.append(f"layout names {folder}, which does not exist")
            continue
        named_folders.add(folder.rstrip("/"))
        named_text[folder.rstrip("/")] = body
        for sub in re.findall(r"(?<![\w/])([\w-]+)/(?=[\s,;)]|$)", body):
            if os.path.isdir(os.path.join(path, sub)):
                named_folders.add(folder + sub)
            elif not os.path.isdir(os.path.join(root, sub)):
                errors.append(f"layout names {sub}/ under {folder}, which does not exist")
        files = [f for _, _, names in os.walk(path) for f in names]  # the folder and its subfolders
        for name in FILE_RE.findall(body):
            name = name.split("/")[-1]
            if not fnmatch.filter(files, name):
                errors.append(f"layout names {name} in {folder}, which matches no file there")

    def listed(folder):
        return folder in named_folders or any(f.startswith(folder + "/") for f in named_folders)

    for top in sorted(os.listdir(root)):
        if top.startswith(".") or top in ("build", "out", "node_modules"):
            continue
        if os.path.isdir(os.path.join(root, top)) and not listed(top):
            errors.append(f"folder {top}/ is not in the layout block")
    for parent in ("src", "bench", "tools"):
        base = os.path.join(root, parent)
        for sub in sorted(os.listdir(base)) if os.path.isdir(base) else []:
            if os.path.isdir(os.path.join(base, sub)) and f"{parent}/{sub}" not in named_folders:
                errors.append(f"folder {parent}/{sub}/ is not in the layout block")
    for folder, ext in (("include/collide", (".h", ".h.in")), ("docs", (".md",))):
        body = named_text.get(folder, "")
        patterns = FILE_RE.findall(body)
        for f in sorted(os.listdir(os.path.join(root, folder))):
            if f.endswith(ext) and not any(fnmatch.fnmatch(f, p) for p in patterns):
                errors.append(f"{folder}/{f} is not named in the layout block")

    m = re.search(r"^Targets:(.*?)(?:\n\s*\n|\Z)", text, flags=re.S | re.M)
    listed_targets = set(re.findall(r"\bfuzz_\w+", m.group(1))) if m else set()
    fuzz_dir = os.path.join(root, "fuzz")
    actual = {f[:-2] for f in os.listdir(fuzz_dir) if re.match(r"^fuzz_\w+\.c$", f)} if os.path.isdir(fuzz_dir) else set()
    for t in sorted(actual - listed_targets):
        errors.append(f"fuzz target {t} (fuzz/{t}.c) is not in the 'Targets:' list")
    for t in sorted(listed_targets - actual):
        errors.append(f"the 'Targets:' list names {t}, which has no fuzz/{t}.c")

    for e in errors:
        print("check_contributing: " + e)
    print(f"check_contributing: {len(entries)} layout folders, {len(actual)} fuzz targets, {len(errors)} errors")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
