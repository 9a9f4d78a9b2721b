#!/usr/bin/env python3
"""Register two scans with sextant.match and print the transform and whether to trust it.

    PYTHONPATH=<build>/python python3 python/examples/register_pair.py            # data/velodyne_pair
    PYTHONPATH=<build>/python python3 python/examples/register_pair.py REF IN [--gt MATRIX.txt]

Without arguments it registers the outdoor Velodyne pair in data/ and compares the result with the
pair's reference transform (data/velodyne_pair/fast_gicp_relative.txt: p_reference = T · p_input).
"""
import argparse
import pathlib
import sys

import numpy as np

import sextant

DATA = pathlib.Path(__file__).resolve().parents[2] / "data" / "velodyne_pair"


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("reference", nargs="?", default=DATA / "fast_gicp_251370668.pcd")
    parser.add_argument("input", nargs="?", default=DATA / "fast_gicp_251371071.pcd")
    parser.add_argument("--gt", help="4×4 or 3×4 text matrix mapping input into reference")
    parser.add_argument("--method", default="mlndt")
    args = parser.parse_args(argv)
    gt = args.gt
    if gt is None and args.reference == parser.get_default("reference"):
        gt = DATA / "fast_gicp_relative.txt"

    reference = sextant.read_cloud(args.reference)
    moving = sextant.read_cloud(args.input)
    result = sextant.match(reference, moving, method=args.method)

    np.set_printoptions(precision=6, suppress=True)
    print(f"reference: {args.reference} ({len(reference)} points)")
    print(f"input:     {args.input} ({len(moving)} points)")
    print("T (p_reference = T · p_input):")
    print(result.T)
    reason = f" ({result.trust_reason})" if result.trust_reason else ""
    print(f"trust: {result.trust}{reason}; overlap {result.overlap:.3f}, {result.iterations} iterations, "
          f"{result.seconds:.3f} s; search: {result.search}")
    if gt is not None:
        truth = np.eye(4)
        values = np.loadtxt(gt).reshape(-1)
        truth[: len(values) // 4] = values.reshape(-1, 4)
        error = np.linalg.inv(truth) @ result.T
        R = error[:3, :3]  # rotation angle from sin and cos (robust near 0)
        sin = np.linalg.norm([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]]) / 2
        angle = np.degrees(np.arctan2(sin, (np.trace(R) - 1) / 2))
        print(f"error against {gt}: {100 * np.linalg.norm(error[:3, 3]):.2f} cm, {angle:.3f} deg")
    return 0 if result.trusted else 3


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
