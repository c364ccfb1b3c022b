#!/usr/bin/env python3
"""Generates the layouts the scale benchmarks check, from the corpus.

    python3 tests/bench/layouts.py OUT LAYOUT [N] [--corpus DIR]

Every layout is made of copies of real corpus files (test input: written
under OUT at run time, never committed). The files are taken in a fixed
order (sorted paths) and cycled when N is larger than the corpus, so a
layout of a given N is the same on every run and every machine.

Layouts:
  grouped N   N corpus modules in one folder (one task of N modules)
  spread N    the same N modules, each in a folder of its own (N tasks)
  damaged N   N corpus modules in one folder, each damaged at a few
              seeded places (text cut out, junk put in, the tail cut off)
  backups N   N controller backups (copies of the corpus's backups, each
              in a folder of its own), as a fleet's backups in one repository
  home N      one repository of N dated backups of one cell, copies of the
              corpus backups that have a HOME folder (the one with most
              HOME modules first)
  repos N     N small repositories (copies of the corpus repositories of
              at most 10 modules) side by side
  corpus N    N copies of the whole corpus tree side by side (the server's
              workspace of many repositories; 12 copies: ~10,000 modules)

Prints the number of modules and their bytes.
"""

import argparse
import os
import random
import shutil
import sys
from pathlib import Path

MODULE_EXT = {".mod", ".modx", ".sys", ".sysx", ".prg"}


def is_module(path):
    return path.suffix.lower() in MODULE_EXT


def modules(corpus):
    return sorted(p for p in corpus.rglob("*") if p.is_file() and is_module(p))


def copy_tree(src, dst):
    shutil.copytree(src, dst, symlinks=False, dirs_exist_ok=True)


def is_task_folder(name):
    low = name.lower()
    return (low.startswith("task") and low[4:].isdigit()) or low.startswith("t_rob")


def backups(corpus):
    """Backup roots: folders with a RAPID folder holding task folders."""
    out = []
    for rapid in sorted(corpus.rglob("*")):
        if rapid.is_dir() and rapid.name.upper() == "RAPID":
            if any(c.is_dir() and is_task_folder(c.name) for c in rapid.iterdir()):
                out.append(rapid.parent)
    # A backup inside another (a copy kept within) is copied with it.
    roots = [b for b in out if not any(o != b and o in b.parents for o in out)]
    return roots


def count_modules(folder):
    return sum(1 for p in folder.rglob("*") if p.is_file() and is_module(p))


def damage(text, rng):
    """The text with a few seeded changes: spans cut out, junk put in, and
    sometimes the tail cut off."""
    junk = ["(", ")", ";", "[", "ENDIF", "IF", ":=", "\"", "PROC", ",", "\\", "%"]
    for _ in range(rng.randint(2, 6)):
        if not text:
            break
        at = rng.randrange(len(text))
        if rng.random() < 0.5:
            text = text[:at] + text[at + rng.randint(1, 40):]
        else:
            text = text[:at] + rng.choice(junk) + text[at:]
    if rng.random() < 0.3 and text:
        text = text[: rng.randrange(len(text))]
    return text


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("layout")
    ap.add_argument("n", type=int, nargs="?", default=0)
    default = os.environ.get("RAPID_CORPUS") or str(Path(__file__).resolve().parents[2].parent / "shared" / "corpus")
    ap.add_argument("--corpus", default=default)
    args = ap.parse_args()
    corpus = Path(args.corpus)
    if not corpus.is_dir():
        sys.exit(f"no corpus at {corpus} (set RAPID_CORPUS or --corpus)")
    out = Path(args.out)
    if out.exists():
        shutil.rmtree(out)
    out.mkdir(parents=True)
    n = args.n
    all_modules = modules(corpus)

    if args.layout in ("grouped", "spread", "damaged"):
        rng = random.Random(27)
        for i in range(n):
            src = all_modules[i % len(all_modules)]
            name = f"{i:05}_{src.name}"
            dst = out / name if args.layout != "spread" else out / f"{i:05}" / src.name
            dst.parent.mkdir(parents=True, exist_ok=True)
            if args.layout == "damaged":
                text = src.read_bytes().decode("latin-1")
                dst.write_bytes(damage(text, rng).encode("latin-1"))
            else:
                shutil.copyfile(src, dst)
    elif args.layout == "backups":
        roots = backups(corpus)
        for i in range(n):
            src = roots[i % len(roots)]
            copy_tree(src, out / f"{i:03}_{src.name}")
    elif args.layout == "home":
        roots = [b for b in backups(corpus) if (b / "HOME").is_dir() or (b / "home").is_dir()]
        roots.sort(key=lambda b: (-count_modules(b / "HOME"), str(b)))
        for i in range(n):
            src = roots[i % len(roots)]
            copy_tree(src, out / f"{src.name}_{2020 + i // 12}-{1 + i % 12:02}-01")
    elif args.layout == "repos":
        repos = [r for r in sorted(corpus.iterdir()) if r.is_dir() and 0 < count_modules(r) <= 10]
        for i in range(n):
            src = repos[i % len(repos)]
            copy_tree(src, out / f"{i:04}_{src.name}")
    elif args.layout == "corpus":
        for i in range(n):
            copy_tree(corpus, out / f"copy{i:02}")
    else:
        sys.exit(f"unknown layout {args.layout}")

    files = [p for p in out.rglob("*") if p.is_file() and is_module(p)]
    size = sum(p.stat().st_size for p in files)
    print(f"{args.layout} {n}: {len(files)} modules, {size} bytes")


if __name__ == "__main__":
    main()
