#!/usr/bin/env python3
"""Runs of scripts/check-change-detection.sh side by side: per scene and resolution, each
directory's wrong labels, with its "moved" labels for targets that stayed and on fixed
bodies (scripts/change_detection_table.py defines them).

    python3 scripts/change_detection_compare.py out/a/visibility out/b/visibility ...

A run missing from a directory shows "-". Labels steer the next pushes, so two directories'
runs share their seeds and their first pushes, not every push.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from change_detection_table import counts, runs_of  # noqa: E402


def main():
    roots = sys.argv[1:]
    if not roots:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    cells = {}
    for column, root in enumerate(roots):
        for scene, resolution, rows in runs_of(root):
            wrong, stayed, fixed = counts(rows)
            cells.setdefault((scene, resolution), {})[column] = (
                f"{wrong}/{len(rows)} ({100 * wrong / len(rows):.1f} %), {stayed}, {fixed}")
    print("| scene | resolution | " + " | ".join(roots) + " |")
    print("|---|---|" + "---|" * len(roots))
    for (scene, resolution), by_column in sorted(cells.items()):
        print(f"| {scene} | {resolution} | "
              + " | ".join(by_column.get(c, "-") for c in range(len(roots))) + " |")
    print()
    print("Each cell: wrong labels / pushes (rate), \"moved\" for a target that stayed, "
          "\"moved\" on a fixed body.")
    return 0


if __name__ == "__main__":
    sys.exit(main())
