#!/usr/bin/env python3
# When a fluidised dose starts to leave and how far it has gone, per run and as mean ± standard
# error per sweep point, from a stored fluidisation sweep's bed.csv (the ORF and dose-remaining
# series at every snapshot; docs/fluidisation.md). Times are snapshot times (1 ms apart in the
# fluidisation cases), so each is the first snapshot at which the condition holds:
#   first departure  the dose remaining in the reservoir has fallen below 99 %
#   ORF -10 %        the ORF has fallen below 90 % of its value at t = 0
#   ORF <= 0.1       the ORF has fallen to 0.1 (the fluidisation_time metric interpolates this)
#   ORF at T ms      the ORF at the snapshot nearest T (default 17 ms, next to 17.3 ms, the last frame
#                    of the thesis' fig. 6.6; --at changes it; "-" when none lies within 0.5 ms)
# A run whose dose never gets there shows "-" and is left out of that column's mean (the count
# says how many runs it holds).
#   python3 scripts/fluidisation-timeline.py cases/baselines/sweeps/fluidisation_glass/bed.csv
import argparse
import csv
import math
import statistics
import sys
from collections import defaultdict

FIXED = ("point", "seed", "engine", "time", "orf", "dose_remaining")


def first_time(series, condition):
    """The first snapshot time (ms) at which condition(orf, dose, orf_at_start) holds, or None."""
    orf0 = series[0][1]
    for t, orf, dose in series:
        if condition(orf, dose, orf0):
            return 1e3 * t
    return None


def mean_and_error(values):
    """Mean ± standard error of the values that are not None, and how many there were."""
    kept = [v for v in values if v is not None]
    if not kept:
        return "-"
    mean = statistics.fmean(kept)
    error = statistics.stdev(kept) / math.sqrt(len(kept)) if len(kept) > 1 else float("nan")
    note = "" if len(kept) == len(values) else f" ({len(kept)} of {len(values)})"
    return f"{mean:.2f} ± {error:.2f}{note}"


def shown_value(text):
    """An axis value as the sweep wrote it, shortened to the digits that matter."""
    try:
        return f"{float(text):.6g}"
    except (ValueError, TypeError):
        return text


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("bed_csv", help="a stored fluidisation sweep's bed.csv")
    parser.add_argument("--at", type=float, default=17.0, help="time (ms) of the ORF column (default 17)")
    parser.add_argument("--runs", action="store_true", help="print every run, not only the points")
    args = parser.parse_args()
    try:
        with open(args.bed_csv, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        sys.exit(f"{args.bed_csv}: cannot be read: {e.strerror}")
    if not rows or any(k not in rows[0] for k in FIXED):
        sys.exit(f"{args.bed_csv}: not a fluidisation bed.csv (columns {', '.join(FIXED)} and the sweep's axes expected)")
    axes = [k for k in rows[0] if k not in FIXED]
    runs = defaultdict(list)
    for line, r in enumerate(rows, start=2):
        try:
            sample = (float(r["time"]), float(r["orf"]), float(r["dose_remaining"]))
            key = (int(r["point"]), tuple(shown_value(r[a]) for a in axes), r["engine"], int(r["seed"]))
        except (ValueError, TypeError):
            sys.exit(f"{args.bed_csv}: line {line}: a short row, or point, seed, time, orf or dose_remaining "
                     "is not a number")
        if None in (key[2], *key[1]):
            sys.exit(f"{args.bed_csv}: line {line}: a short row")
        runs[key].append(sample)

    columns = ("first departure (ms)", "ORF -10 % (ms)", "ORF <= 0.1 (ms)", f"ORF at {args.at:g} ms")
    points = defaultdict(lambda: [[] for _ in columns])
    for (point, values, engine, seed), series in sorted(runs.items()):
        series.sort()
        nearest = min(series, key=lambda s: abs(1e3 * s[0] - args.at))
        found = (first_time(series, lambda orf, dose, orf0: dose < 0.99),
                 first_time(series, lambda orf, dose, orf0: orf < 0.9 * orf0),
                 first_time(series, lambda orf, dose, orf0: orf <= 0.1),
                 nearest[1] if abs(1e3 * nearest[0] - args.at) <= 0.5 else None)
        for column, value in zip(points[(point, values, engine)], found):
            column.append(value)
        if args.runs:
            shown = ["-" if v is None else f"{v:.3f}" for v in found]
            print(f"point {point} {' '.join(values)} {engine} seed {seed}: " + ", ".join(f"{c} {s}" for c, s in zip(columns, shown)))
    print("| point | " + " | ".join(axes) + " | engine | runs | " + " | ".join(columns) + " |")
    print("|---" * (3 + len(axes) + len(columns)) + "|")
    for (point, values, engine), found in sorted(points.items()):
        shown = [mean_and_error(v) for v in found]
        print(f"| {point} | " + " | ".join(values) + f" | {engine} | {len(found[0])} | " + " | ".join(shown) + " |")


if __name__ == "__main__":
    main()
