#!/usr/bin/env python3
"""Splits the learning gap of the benchmark scenes (issue 32) into its three causes.

On the frames of `relmap-sim dataset` (train: one seed, test: another, so new object
poses), for each scene and replication:

  oracle   a batch random forest (300 trees, equal class priors) on *every* supervoxel of the training frames: what the
           features can separate at all ("the features cannot");
  rf@random, rf@choice
           the same forest on `budget` samples drawn uniformly, or on the samples the
           default's choice map picked (relmap-cmm --active --picks-out): what a strong
           learner makes of each sample set ("the exploration picks badly" when
           rf@choice < rf@random);
  cmm@random, cmm@choice, and --extra CONFIG@choice
           relmap-cmm on the same two sample sets ("the classifier cannot" where
           cmm@random < rf@random).

The choice map here picks from one pool of all training frames' supervoxels, not one frame
at a time as `relmap-sim run` does: the pool-based form of the same rule. Scores are on
every supervoxel of the test frames: balanced accuracy at 0.5 and the thresholded-soft
accuracy of docs/method.md §6 (the metric of docs/results.md §K). Each replication r
draws with seed r (the random samples and the choice map's draws alike).

usage: learning-gap.py --data DIR [--scenes A,B] [--budget 200] [--replications 5]
       [--cmm build/server/tools/relmap-cmm] [--extra paper2018,corrected:alpha=1]
DIR holds <scene>-s1.csv (train) and <scene>-s2.csv (test), as scripts/learning-gap.sh
exports them.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import numpy as np
from sklearn.ensemble import RandomForestClassifier


def load(path):
    data = np.loadtxt(path, delimiter=",", skiprows=1)
    return data[:, 1:], data[:, 0].astype(int)


def scores(p, y):
    """Balanced accuracy at 0.5 and thresholded-soft accuracy (method.md §6)."""
    obj, back = y == 1, y == 0
    hit = p >= 0.5
    balanced = 0.5 * (np.mean(hit[obj]) + np.mean(~hit[back]))
    tp = np.sum(np.where(obj & hit, p, 0.0))
    tn = np.sum(np.where(back & ~hit, 1.0 - p, 0.0))
    thresholded = 0.5 * (tp / obj.sum() + tn / back.sum())
    return balanced, thresholded


def equal_prior_forest(x, y, xt, seed):
    """P(moveable) of a 300-tree forest with equal class priors: its vote shares divided
    by the training class frequencies, renormalised, as scripts/scene_acceptance.py
    decides (the classes are ~1:9, and both metrics weigh them equally)."""
    rf = RandomForestClassifier(n_estimators=300, n_jobs=2, random_state=seed)
    rf.fit(x, y)
    votes = rf.predict_proba(xt) / np.array([(y == c).mean() for c in rf.classes_])
    return votes[:, 1] / votes.sum(axis=1)


def forest_scores(x, y, xt, yt, seed):
    if len(set(y)) < 2:  # one class only: the forest says that class everywhere
        return scores(np.full(len(yt), float(y[0])), yt)
    return scores(equal_prior_forest(x, y, xt, seed), yt)


def run_cmm(cmm, config, train, test, seed, extra_args, picks=None):
    args = [cmm, "--train", train, "--test", test, "--config", config, "--seed", str(seed)]
    args += extra_args
    if picks:
        args += ["--picks-out", picks]
    report = json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)
    t = report["test"]
    return t["balanced_accuracy"], t["thresholded_soft"]["accuracy"]


def write_rows(path, x, y, rows):
    with open(path, "w") as f:
        f.write("label," + ",".join(f"f{i + 1}" for i in range(x.shape[1])) + "\n")
        for r in rows:
            f.write(f"{y[r]}," + ",".join(repr(float(v)) for v in x[r]) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--data", required=True)
    ap.add_argument("--scenes", default="ShelfClutter,Workbench,KitchenCounter")
    ap.add_argument("--budget", type=int, default=200)
    ap.add_argument("--replications", type=int, default=5)
    ap.add_argument("--cmm", default="build/server/tools/relmap-cmm")
    ap.add_argument("--extra", default="paper2018,corrected:alpha=1",
                    help="further relmap-cmm configurations, run with --active")
    a = ap.parse_args()
    extras = [e for e in a.extra.split(",") if e]
    columns = ["oracle", "rf@random", "rf@choice", "cmm@random", "cmm@choice"]
    columns += [f"{e}@choice" for e in extras]
    print(f"budget {a.budget}, {a.replications} replications; per cell: balanced accuracy / "
          "thresholded-soft accuracy, mean (min-max of balanced) over replications")
    print("| scene | train rows (moveable) | test rows (moveable) | " + " | ".join(columns) + " |")
    print("|---" * (len(columns) + 3) + "|")
    with tempfile.TemporaryDirectory() as tmp:
        for scene in a.scenes.split(","):
            train = os.path.join(a.data, f"{scene}-s1.csv")
            test = os.path.join(a.data, f"{scene}-s2.csv")
            x, y = load(train)
            xt, yt = load(test)
            results = {c: [] for c in columns}
            for r in range(a.replications):
                seed = r + 1
                picks = os.path.join(tmp, "picks.txt")
                budget = ["--active", "--budget", str(a.budget)]
                results["cmm@choice"].append(run_cmm(a.cmm, "corrected", train, test, seed,
                                                     budget, picks))
                chosen = np.loadtxt(picks, dtype=int)
                uniform = np.random.default_rng(seed).choice(len(y), a.budget, replace=False)
                random_csv = os.path.join(tmp, "random.csv")
                write_rows(random_csv, x, y, uniform)
                results["cmm@random"].append(run_cmm(a.cmm, "corrected", random_csv, test,
                                                     seed, []))
                results["rf@random"].append(forest_scores(x[uniform], y[uniform], xt, yt, seed))
                results["rf@choice"].append(forest_scores(x[chosen], y[chosen], xt, yt, seed))
                for e in extras:
                    results[f"{e}@choice"].append(run_cmm(a.cmm, e, train, test, seed, budget))
                if r == 0:  # the oracle does not depend on the draws
                    oracle = forest_scores(x, y, xt, yt, seed)
                results["oracle"].append(oracle)
                print(f"  {scene}: replication {r + 1}/{a.replications} done", file=sys.stderr)
            cells = []
            for c in columns:
                v = np.array(results[c], dtype=float)
                cells.append(f"{v[:, 0].mean():.2f} / {v[:, 1].mean():.2f} "
                             f"({v[:, 0].min():.2f}-{v[:, 0].max():.2f})")
            print(f"| {scene} | {len(y)} ({y.sum()}) | {len(yt)} ({yt.sum()}) | "
                  + " | ".join(cells) + " |", flush=True)


if __name__ == "__main__":
    main()
