#!/usr/bin/env python3
"""Per method of registration results: the sample's share of the scan, the matched share, the
matching time and Jarque–Bera of each error parameter (issue 66's measured causes, docs/experiments.md E6).

    scripts/sample_shares.py results/e06_sampling_strategies/runs.csv [more runs.csv ...]

Reads a `registration` kind's runs.csv (columns kept_fraction, matched_percent, input_points,
seconds_align, success, error_tx … error_gamma). Prints, per method: the mean kept share [%] (the sample
against the whole input scan), the mean matched share of the scan [%] (kept × matched, table 5.9's
"matched points"), the mean sample size, the median matching time [ms], the successes, and Jarque–Bera
per parameter (n/6 · (S² + (K − 3)²/4) of the errors; above 5.99 rejects normality at 5 %).
"""
import csv
import statistics
import sys

PARAMETERS = ("tx", "ty", "tz", "alpha", "beta", "gamma")


def jarque_bera(values):
    """n/6 · (S² + (K − 3)²/4) with the sample skewness S and kurtosis K (moments over n)."""
    n = len(values)
    mean = sum(values) / n
    d = [v - mean for v in values]
    m2 = sum(x * x for x in d) / n
    if m2 == 0:
        return 0.0
    skew = (sum(x**3 for x in d) / n) / m2**1.5
    kurtosis = (sum(x**4 for x in d) / n) / m2**2
    return n / 6.0 * (skew * skew + (kurtosis - 3.0) ** 2 / 4.0)


def summarize(rows):
    """Method → dict of the measured shares, times and JB per parameter."""
    by_method = {}
    for r in rows:
        by_method.setdefault(r["method"], []).append(r)
    out = {}
    for method, rs in by_method.items():
        kept = [float(r["kept_fraction"]) for r in rs]
        out[method] = {
            "runs": len(rs),
            "kept_percent": 100.0 * statistics.mean(kept),
            "matched_percent": statistics.mean(k * float(r["matched_percent"]) for k, r in zip(kept, rs)),
            "points": statistics.mean(float(r["input_points"]) for r in rs),
            "align_ms": 1000.0 * statistics.median(float(r["seconds_align"]) for r in rs),
            "successes": sum(float(r["success"]) > 0.5 for r in rs),
            "jarque_bera": {p: jarque_bera([float(r["error_" + p]) for r in rs]) for p in PARAMETERS},
        }
    return out


def main(paths):
    if not paths:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    for path in paths:
        with open(path, newline="") as f:
            table = summarize(list(csv.DictReader(f)))
        print(path)
        for method, s in table.items():
            jb = " ".join(f"{p} {v:.0f}" for p, v in s["jarque_bera"].items())
            print(f"  {method:16s} kept {s['kept_percent']:5.1f} %  matched {s['matched_percent']:5.1f} %  "
                  f"points {s['points']:7.0f}  matching {s['align_ms']:6.2f} ms  "
                  f"success {s['successes']}/{s['runs']}  JB {jb}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
