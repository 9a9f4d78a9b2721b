"""scripts/sample_shares.py on a hand-written runs table with known shares, times and Jarque–Bera."""
import importlib.util
import pathlib

SCRIPT = pathlib.Path(__file__).resolve().parents[2] / "scripts" / "sample_shares.py"
spec = importlib.util.spec_from_file_location("sample_shares", SCRIPT)
sample_shares = importlib.util.module_from_spec(spec)
spec.loader.exec_module(sample_shares)


def row(method, kept, matched, points, seconds, success, tx):
    r = {"method": method, "kept_fraction": kept, "matched_percent": matched, "input_points": points,
         "seconds_align": seconds, "success": success}
    for p in sample_shares.PARAMETERS:
        r["error_" + p] = "0"
    r["error_tx"] = tx
    return r


def test_jarque_bera_of_a_known_sample():
    # [0, 0, 0, 0, 10]: mean 2, m2 16, m3 96, m4 832, S = 1.5, K = 3.25 → 5/6 · (2.25 + 0.015625).
    assert abs(sample_shares.jarque_bera([0, 0, 0, 0, 10]) - 5.0 / 6.0 * (2.25 + 0.0625 / 4.0)) < 1e-12
    assert sample_shares.jarque_bera([3.0, 3.0, 3.0]) == 0.0


def test_shares_times_and_successes_per_method():
    rows = [row("fbs", "0.8", "90", "800", "0.010", "1", "0"),
            row("fbs", "0.6", "50", "600", "0.030", "0", "10"),
            row("fbs", "0.7", "100", "700", "0.020", "1", "0"),
            row("fbs", "0.9", "100", "900", "0.040", "1", "0"),
            row("fbs", "1.0", "100", "1000", "0.050", "1", "0"),
            row("gbs", "0.25", "100", "250", "0.002", "1", "0")]
    out = sample_shares.summarize(rows)
    f = out["fbs"]
    assert f["runs"] == 5 and f["successes"] == 4
    assert abs(f["kept_percent"] - 80.0) < 1e-12
    assert abs(f["matched_percent"] - (72 + 30 + 70 + 90 + 100) / 5.0) < 1e-12
    assert abs(f["points"] - 800.0) < 1e-12
    assert abs(f["align_ms"] - 30.0) < 1e-12
    assert abs(f["jarque_bera"]["tx"] - sample_shares.jarque_bera([0, 10, 0, 0, 0])) < 1e-12
    assert out["gbs"]["kept_percent"] == 25.0
