#!/usr/bin/env python3
"""N samples of each class of a relmap-cmm CSV, evenly spread over the file.

usage: balanced-subsample.py IN.csv N > OUT.csv

A robot that explores with the choice map labels both classes about equally
(docs/history/results-2026-11-12.md §S2.7), while a simulator export holds every supervoxel of
every frame (a few percent moveable): this turns the export into the training
stream such a robot would have collected over all the frames — every
(count/N)-th sample of each class, in file order, deterministically.
"""
import sys


def main():
    path, per_class = sys.argv[1], int(sys.argv[2])
    with open(path) as f:
        lines = [l for l in f if l.split(",", 1)[0].strip() in ("0", "1")]
    keep = set()
    for label in ("0", "1"):
        rows = [i for i, l in enumerate(lines) if l.startswith(label + ",")]
        n = min(per_class, len(rows))
        keep.update(rows[(k * len(rows)) // n] for k in range(n))
    sys.stdout.writelines(lines[i] for i in sorted(keep))


if __name__ == "__main__":
    main()
