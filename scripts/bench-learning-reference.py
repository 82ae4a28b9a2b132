#!/usr/bin/env python3
"""Batch upper reference for relmap-bench-learning: a 200-tree random forest, an
RBF SVM and a logistic regression (scikit-learn; each one's settings and class
weights chosen by 3-fold cross-validation on the training set, balanced accuracy),
each trained on a stream's whole training set at once and scored on its test set,
in the benchmark's table schema (CSV).

Reads STREAMS/NAME.rK.train.csv and STREAMS/NAME.rK.test.csv (label first, one
header line), as relmap-bench-learning --out DIR writes them in DIR/streams.
Rows summarise the replications K like the C++ program: balanced accuracy mean
and min, the other scores as means. Batch learners have no per-sample update, so
the update latency cells are empty; predict_us is per test sample.
"""
import argparse
import collections
import csv
import glob
import math
import os
import sys
import time

import numpy as np
from sklearn.ensemble import RandomForestClassifier
from sklearn.linear_model import LogisticRegression
from sklearn.model_selection import GridSearchCV, StratifiedKFold
from sklearn.pipeline import Pipeline
from sklearn.preprocessing import StandardScaler
from sklearn.svm import SVC

COLUMNS = ["stream", "learner", "replications", "balanced_accuracy_mean",
           "balanced_accuracy_min", "soft_accuracy", "log_loss", "brier", "components",
           "update_p50_us", "update_p99_us", "predict_us"]


def read(path):
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return data[:, 1:], data[:, 0].astype(int)


# Unweighted, or each class weighted by the inverse of its frequency: a robot's pushes
# are not balanced (a physical run's targets are mostly background), and the score is
# the balanced accuracy at 0.5, so an upper reference may choose either.
WEIGHTS = [None, "balanced"]


def cross_validation(y, seed):
    """3-fold stratified folds, or None when a class has fewer than 2 samples."""
    folds = min(3, int(np.min(np.bincount(y, minlength=2))))
    return StratifiedKFold(folds, shuffle=True, random_state=seed) if folds >= 2 else None


def tuned_svm(x, y, seed):
    """An RBF SVM with C and gamma chosen by 3-fold cross-validation on the
    training set (balanced accuracy): an upper reference must not lose to an
    untuned default. The grid is around gamma="scale" = 1 / (p · Var X), on the
    raw features and on standardised ones: standardisation blows near-constant
    dimensions (the synthetic streams' ambient noise) up to the signal's size,
    but evens out the real features' scales; the folds choose. P(1|x) by Platt
    scaling, seeded for reproducibility."""
    svm = Pipeline([("scale", "passthrough"),
                    ("svm", SVC(kernel="rbf", probability=True, random_state=seed))])
    cv = cross_validation(y, seed)
    if cv is None:
        return svm.set_params(svm__gamma="scale")
    raw = 1.0 / (x.shape[1] * x.var()) if x.var() > 0 else 1.0
    standard = 1.0 / x.shape[1]  # Var = 1 after StandardScaler
    grid = [{"scale": ["passthrough"], "svm__C": [1.0, 10.0, 100.0],
             "svm__gamma": [raw / 10, raw, raw * 10], "svm__class_weight": WEIGHTS},
            {"scale": [StandardScaler()], "svm__C": [1.0, 10.0, 100.0],
             "svm__gamma": [standard / 10, standard, standard * 10],
             "svm__class_weight": WEIGHTS}]
    return GridSearchCV(svm, grid, scoring="balanced_accuracy", cv=cv)


def tuned_logistic(x, y, seed):
    """A standardised L2 logistic regression, C (1e-2 … 1e2) chosen by 3-fold
    cross-validation on the training set (balanced accuracy): the linear batch
    baseline, where `sgd` is the online one."""
    model = Pipeline([("scale", StandardScaler()),
                      ("logistic", LogisticRegression(max_iter=5000, random_state=seed))])
    cv = cross_validation(y, seed)
    if cv is None:
        return model
    return GridSearchCV(model, {"logistic__C": [0.01, 0.1, 1.0, 10.0, 100.0],
                                "logistic__class_weight": WEIGHTS},
                        scoring="balanced_accuracy", cv=cv)


def tuned_forest(y, seed):
    """200 trees (enough that the forest's score no longer moves with the seed),
    the class weights chosen by 3-fold cross-validation (balanced accuracy)."""
    forest = RandomForestClassifier(n_estimators=200, random_state=seed)
    cv = cross_validation(y, seed)
    if cv is None:
        return forest
    return GridSearchCV(forest, {"class_weight": [None, "balanced_subsample"]},
                        scoring="balanced_accuracy", cv=cv)


def learners(seed):
    return {
        "random_forest": lambda x, y: tuned_forest(y, seed),
        "rbf_svm": lambda x, y: tuned_svm(x, y, seed),
        "logistic_regression": lambda x, y: tuned_logistic(x, y, seed),
    }


def scores(p, y):
    """The benchmark's metrics (server/exploration/metrics.h), moveable = 1."""
    def recall(label):
        mask = y == label
        return float(np.mean((p[mask] >= 0.5) == (label == 1))) if mask.any() else None
    r0, r1 = recall(0), recall(1)
    balanced = None if r0 is None or r1 is None else 0.5 * (r0 + r1)
    objects, background = np.sum(y == 1), np.sum(y == 0)
    soft = None
    if objects > 0 and background > 0:  # ½(tp/G_obj + tn/G_back), the paper's soft metric
        soft = 0.5 * (np.sum(p[y == 1]) / objects + np.sum(1 - p[y == 0]) / background)
    clipped = np.clip(p, 1e-15, 1 - 1e-15)
    log_loss = float(-np.mean(np.where(y == 1, np.log(clipped), np.log(1 - clipped))))
    brier = float(np.mean((p - y) ** 2))
    return balanced, soft, log_loss, brier


def mean(values):
    defined = [v for v in values if v is not None]
    return sum(defined) / len(defined) if defined else None


def cell(value):
    return "" if value is None or not math.isfinite(value) else f"{value:.6g}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--streams", required=True, help="directory of NAME.rK.{train,test}.csv")
    parser.add_argument("--out", help="CSV file to write (default: standard output only)")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()

    replications = collections.defaultdict(list)  # stream -> [(train path, test path)]
    for train in sorted(glob.glob(os.path.join(args.streams, "*.train.csv"))):
        stream = os.path.basename(train)[: -len(".train.csv")].rsplit(".r", 1)[0]
        replications[stream].append((train, train[: -len(".train.csv")] + ".test.csv"))
    if not replications:
        sys.exit(f"bench-learning-reference: no *.train.csv in {args.streams}")

    rows = []
    for stream, files in replications.items():
        for name, make in learners(args.seed).items():
            results, predict_us = [], []
            for train, test in files:
                x, y = read(train)
                xt, yt = read(test)
                model = make(x, y)
                if len(set(y)) < 2:  # one class only: nothing to fit, predict it
                    p = np.full(len(yt), float(y[0]))
                    predict_us.append(0.0)
                else:
                    model.fit(x, y)
                    start = time.perf_counter()
                    p = model.predict_proba(xt)[:, list(model.classes_).index(1)]
                    predict_us.append((time.perf_counter() - start) * 1e6 / len(yt))
                results.append(scores(p, yt))
            balanced = [r[0] for r in results if r[0] is not None]
            rows.append([stream, name, len(files), cell(mean(balanced)),
                         cell(min(balanced) if balanced else None),
                         cell(mean([r[1] for r in results])), cell(mean([r[2] for r in results])),
                         cell(mean([r[3] for r in results])), "", "", "", cell(mean(predict_us))])
            print(f"reference: {stream} {name}: balanced accuracy {rows[-1][3] or 'undefined'}",
                  file=sys.stderr)

    writer = csv.writer(sys.stdout, lineterminator="\n")
    writer.writerow(COLUMNS)
    writer.writerows(rows)
    if args.out:
        with open(args.out, "w", newline="") as f:
            out = csv.writer(f, lineterminator="\n")
            out.writerow(COLUMNS)
            out.writerows(rows)


if __name__ == "__main__":
    main()
