#!/usr/bin/env python3
"""Markdown tables from relmap-bench-learning's table.csv, for docs/results.md.

usage: bench-learning-markdown.py TABLE.csv [--metric balanced_accuracy_mean]

Prints one pivot table (a row per stream, a column per learner, the metric's
value; the best online learner of each row in bold), then the learners' mean
over all streams. Nothing is retyped: the docs' tables come from this script.
"""
import argparse
import csv

ONLINE_EXCLUDED = {"random_forest", "rbf_svm", "logistic_regression"}  # batch, not online


def pivot(rows, metric, lower_is_better=False):
    """The table's lines from table.csv's rows (csv.DictReader's dicts)."""
    streams, learners = [], []
    for r in rows:
        if r["stream"] not in streams:
            streams.append(r["stream"])
        if r["learner"] not in learners:
            learners.append(r["learner"])
    value = {(r["stream"], r["learner"]): r[metric] for r in rows}
    lines = ["| stream | " + " | ".join(learners) + " |", "|---" * (len(learners) + 1) + "|"]
    totals = {l: [] for l in learners}
    for s in streams:
        cells = {l: value.get((s, l), "") for l in learners}
        numbers = {l: float(v) for l, v in cells.items() if v not in ("", "nan")}
        online = {l: v for l, v in numbers.items() if l not in ONLINE_EXCLUDED}
        best = (min if lower_is_better else max)(online.values()) if online else None
        out = []
        for l in learners:
            if l not in numbers:
                out.append("—")
                continue
            totals[l].append(numbers[l])
            text = f"{numbers[l]:.3f}"
            out.append(f"**{text}**" if best is not None and numbers[l] == best else text)
        lines.append(f"| {s} | " + " | ".join(out) + " |")
    mean = [f"{sum(v) / len(v):.3f}" if len(v) == len(streams) else "—" for v in totals.values()]
    lines.append("| mean | " + " | ".join(mean) + " |")
    return lines


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("table")
    parser.add_argument("--metric", default="balanced_accuracy_mean")
    parser.add_argument("--lower-is-better", action="store_true")
    args = parser.parse_args()
    with open(args.table) as f:
        rows = list(csv.DictReader(f))
    print("\n".join(pivot(rows, args.metric, args.lower_is_better)))


if __name__ == "__main__":
    main()
