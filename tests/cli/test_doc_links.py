#!/usr/bin/env python3
"""Every document the project points to is in the repository: each relative link of every
markdown file resolves, and no file names a document kept outside the project (design notes,
reference sheets or a checkout's neighbour directory). Exit 1 with the offenders listed."""
import os
import re
import subprocess
import sys

ROOT = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# names of documents that lived beside the repository while it was begun, and the way out of it
OUTSIDE = re.compile(r"DESIGN\.md|physics-targets|bullet-notes|openfoam-notes|slurm-notes|style-examples|"
                     r"seed-paper\.txt|\.\./shared")
LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")
# a document named by its path from the top of the repository, in code or prose
NAMED = re.compile(r"(?<![\w./$-])((?:docs|bench/results)/[\w./-]+\.md)\b")

def project_files():
    """The tracked files (a checkout), or every file outside build/ and .git/ (a copy without git)."""
    git = subprocess.run(["git", "-C", ROOT, "ls-files"], capture_output=True, text=True)
    if git.returncode == 0:
        return git.stdout.split()
    return [os.path.relpath(os.path.join(d, f), ROOT) for d, dirs, names in os.walk(ROOT)
            for f in names if not os.path.relpath(d, ROOT).split(os.sep)[0] in ("build", ".git")]


files = project_files()
problems = []
for rel in files:
    path = os.path.join(ROOT, rel)
    if rel == "tests/cli/test_doc_links.py" or not os.path.isfile(path):
        continue
    try:
        text = open(path, encoding="utf-8").read()
    except (UnicodeDecodeError, OSError):
        continue  # binary
    for n, line in enumerate(text.splitlines(), 1):
        if OUTSIDE.search(line):
            problems.append(f"{rel}:{n}: names a document outside the repository: {line.strip()[:100]}")
        for named in NAMED.findall(line):
            if not os.path.exists(os.path.join(ROOT, named)):
                problems.append(f"{rel}:{n}: names {named}, which does not exist")
    if rel.endswith(".md"):
        for n, line in enumerate(text.splitlines(), 1):
            for target in LINK.findall(line):
                if re.match(r"[a-z]+:", target) or target.startswith("#"):
                    continue  # a URL or an anchor in the same page
                target = target.split("#")[0]
                if not os.path.exists(os.path.normpath(os.path.join(os.path.dirname(path), target))):
                    problems.append(f"{rel}:{n}: link to {target}, which does not exist")
print("\n".join(problems) if problems else f"{len(files)} files: every link resolves, no outside documents")
sys.exit(1 if problems else 0)
