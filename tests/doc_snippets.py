#!/usr/bin/env python3
"""Checks every code block of the README and the guide against what it claims to be.

Each ```cpp (or ```js) block is preceded by one marker comment:

  <!-- example: examples/NAME.cpp -->          the block is that whole file
  <!-- example: examples/NAME.cpp:12-20 -->    the block is lines 12 to 20 of it (dedented)
  <!-- compile -->                             the block is a whole program: it must compile
                                                (C++: -fsyntax-only with warnings as errors;
                                                JavaScript: node --check)

With --images DIR it checks the links instead: every local link of the pages names a file
that exists (a page, not a heading in it: GitHub and Doxygen name headings differently), and every picture a guide page shows as images/NAME is in DIR (where
scripts/docs-images wrote them).

A block without a marker, a marker naming a missing file or lines past its end, a block that
differs from its file, or one that does not compile fails the check, with the reason.

  doc_snippets.py --root SRC --cxx C++ [--flags FLAGS] [--include DIR]... [--node NODE] (FILE.md | FOLDER)...
  doc_snippets.py --root SRC --images DIR (FILE.md | FOLDER)...
"""
import argparse
import difflib
import os
import re
import shlex
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

FENCE = re.compile(r"^```(\S*)\s*$")
MARKER = re.compile(r"^<!--\s*(example:\s*(?P<path>[^:\s]+)(:(?P<first>\d+)-(?P<last>\d+))?|(?P<compile>compile))\s*-->\s*$")
CHECKED = {"cpp": "cpp", "c++": "cpp", "js": "js", "javascript": "js"}


def blocks(text):
    """Yields (line number, language, marker line or None, block lines) for each fenced block."""
    lines = text.split("\n")
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        start, lang = i, m.group(1).lower()
        j = i + 1
        while j < len(lines) and lines[j].rstrip() != "```":
            j += 1
        k = start - 1
        while k >= 0 and not lines[k].strip():
            k -= 1
        marker = lines[k].strip() if k >= 0 and lines[k].lstrip().startswith("<!--") else None
        yield start + 1, lang, marker, lines[start + 1:j]
        i = j + 1


def dedent(lines):
    lines = [line.rstrip() for line in lines]
    indents = [len(line) - len(line.lstrip()) for line in lines if line]
    cut = min(indents) if indents else 0
    return [line[cut:] for line in lines]


def check_example(root, where, m, body):
    path = os.path.join(root, m.group("path"))
    if not os.path.isfile(path):
        return f"{where}: {m.group('path')} does not exist"
    with open(path, encoding="utf-8") as f:
        source = f.read().split("\n")
    if source and source[-1] == "":
        source.pop()
    if m.group("first"):
        first, last = int(m.group("first")), int(m.group("last"))
        if not 1 <= first <= last <= len(source):
            return f"{where}: lines {first}-{last} are not in {m.group('path')} ({len(source)} lines)"
        source = source[first - 1:last]
    expected, actual = dedent(source), dedent(body)
    if expected == actual:
        return None
    diff = "\n".join(difflib.unified_diff(expected, actual, m.group("path"), where, lineterm=""))
    return f"{where}: the block differs from {m.group(0)}\n{diff}"


def check_compile(args, where, lang, body):
    suffix = ".cpp" if lang == "cpp" else ".js"
    with tempfile.TemporaryDirectory() as tmp:
        source = os.path.join(tmp, "block" + suffix)
        with open(source, "w", encoding="utf-8") as f:
            f.write("\n".join(body) + "\n")
        if lang == "cpp":
            command = [args.cxx, *shlex.split(args.flags), "-std=c++20", "-fsyntax-only", "-Wall", "-Wextra", "-Wpedantic", "-Werror"]
            command += [f"-I{d}" for d in args.include] + [source]
        elif args.node:
            command = [args.node, "--check", source]
        else:
            print(f"{where}: not checked (no node)")
            return None
        run = subprocess.run(command, capture_output=True, text=True)
        if run.returncode != 0:
            return f"{where}: the block does not compile:\n{run.stdout}{run.stderr}"
    return None


LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")


def check_links(root, name, text, images):
    """Local links of one page that lead nowhere (code blocks and spans left out)."""
    prose = re.sub(r"`[^`\n]*`", "", re.sub(r"```.*?```", "", text, flags=re.S))
    shown, failures = os.path.relpath(name, root), []
    for m in LINK.finditer(prose):
        target, _, anchor = m.group(1).partition("#")
        if not target or re.match(r"^[a-z]+:", target):
            continue
        if anchor and target.endswith(".md"):  # GitHub and Doxygen name headings differently
            failures.append(f"{shown}: the link {m.group(1)} names a heading; link the page")
            continue
        if target.startswith("images/") and os.path.basename(os.path.dirname(name)) == "guide":
            if not os.path.isfile(os.path.join(images, target[len("images/"):])):
                failures.append(f"{shown}: {target} is not among the pictures in {images}")
        elif not os.path.exists(os.path.join(os.path.dirname(name), target)):
            failures.append(f"{shown}: the link {target} leads nowhere")
    return failures


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--root", required=True)
    parser.add_argument("--cxx")
    parser.add_argument("--images")
    parser.add_argument("--include", action="append", default=[])
    parser.add_argument("--flags", default="", help="the build's compiler flags, as one string")
    parser.add_argument("--node")
    parser.add_argument("files", nargs="+")
    args = parser.parse_args()

    names = []
    for name in args.files:  # a folder stands for its *.md files
        if os.path.isdir(name):
            names += sorted(os.path.join(name, n) for n in os.listdir(name) if n.endswith(".md"))
        else:
            names.append(name)
    if args.images:
        failures = []
        for name in names:
            with open(name, encoding="utf-8") as f:
                failures += check_links(args.root, name, f.read(), args.images)
        for failure in failures:
            print(failure, file=sys.stderr)
        print(f"{len(names)} pages' links checked, {len(failures)} lead nowhere")
        return 1 if failures else 0
    if not args.cxx:
        parser.error("--cxx is required to check code blocks")

    failures, jobs, counts = [], [], {"example": 0, "compile": 0}
    for name in names:
        with open(name, encoding="utf-8") as f:
            text = f.read()
        shown = os.path.relpath(name, args.root)
        for line, lang, marker, body in blocks(text):
            if lang not in CHECKED:
                continue
            where = f"{shown}:{line}"
            m = MARKER.match(marker) if marker else None
            if not m:
                failures.append(f"{where}: a ```{lang} block needs <!-- example: FILE[:A-B] --> or <!-- compile --> before it")
            elif m.group("compile"):
                counts["compile"] += 1
                jobs.append((where, CHECKED[lang], body))
            else:
                counts["example"] += 1
                failure = check_example(args.root, where, m, body)
                if failure:
                    failures.append(failure)
    with ThreadPoolExecutor(max_workers=2) as pool:
        failures += [f for f in pool.map(lambda j: check_compile(args, *j), jobs) if f]

    for failure in failures:
        print(failure, file=sys.stderr)
    print(f"{counts['example']} blocks checked against their files, {counts['compile']} compiled, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
