#!/usr/bin/env python3
"""A relmap-cmm CSV with a fraction of its labels flipped: the label noise of a change
detector that is wrong on some pushes, as a fixed, reproducible stream.

usage: flip-labels.py IN.csv FRACTION SEED > OUT.csv

Exactly round(FRACTION * rows) rows, drawn without replacement by Python's Mersenne
Twister seeded with SEED, get the other label; the header and every other row are copied
as they are. Flipped uniformly over both classes, as relmap-bench-learning's built-in
-flip streams are.
"""
import random
import sys


def main():
    path, fraction, seed = sys.argv[1], float(sys.argv[2]), int(sys.argv[3])
    with open(path) as f:
        lines = f.readlines()
    rows = [i for i, l in enumerate(lines) if l.split(",", 1)[0].strip() in ("0", "1")]
    flipped = set(random.Random(seed).sample(rows, round(fraction * len(rows))))
    for i, line in enumerate(lines):
        if i in flipped:
            label, rest = line.split(",", 1)
            line = ("0" if label.strip() == "1" else "1") + "," + rest
        sys.stdout.write(line)


if __name__ == "__main__":
    main()
