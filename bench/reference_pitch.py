#!/usr/bin/env python3
"""Where MulRan 0-107's pitch bias lives (issue 22): each step's pitch against the reference
(`poses.txt`, FAST-LIO2 odometry with a loop-closing pose graph over its keyframes) for the
reference's own lidar-inertial odometry (`lio_odometry_poses.txt`, before that pose graph) and for
a `sextant odometry` run over the same keyframes, binned by the time between the keyframes and by
the length of the step. Then the KITTI drift of both (sextant.metrics.kitti_drift, as `sextant eval`),
in 3D and on the ground plane (aligned, then sextant.metrics.on_ground_plane: x, y and heading
only, as `sextant eval --ground-plane`), which leaves that pitch out.

A bias of the scans or of a registration accrues with the motion (metres) or, for an odometry that
runs at the lidar's 10 Hz between keyframes, with the frames in between (seconds). A correction
that a pose graph spreads evenly over its edges accrues per keyframe: the same in every bin.

  bench/reference_pitch.py [path/to/mulran_riverside02] [odometry folder (--first 0 --scans 108)]
      [build/python]
"""
import os
import sys

import numpy as np

mulran = sys.argv[1] if len(sys.argv) > 1 else "../shared/data/mulran_riverside02"
run = sys.argv[2] if len(sys.argv) > 2 and sys.argv[2] != "-" else None
sys.path.insert(0, sys.argv[3] if len(sys.argv) > 3 else "build/python")
import sextant  # noqa: E402  (the module built beside the CLI)

FIRST, SCANS = 0, 108  # the stretch whose reference holds (../shared/data/README.md)


def poses(path, rows):
    """KITTI rows (3x4, world <- keyframe) as 4x4 matrices."""
    table = np.loadtxt(path)[rows]
    out = np.tile(np.eye(4), (len(table), 1, 1))
    out[:, :3, :] = table.reshape(-1, 3, 4)
    return out


def step_pitch_errors(reference, estimate):
    """The pitch [deg] of each step's error, inv(reference motion) * estimated motion."""
    errors = []
    for k in range(len(reference) - 1):
        truth = np.linalg.inv(reference[k]) @ reference[k + 1]
        moved = np.linalg.inv(estimate[k]) @ estimate[k + 1]
        error = np.linalg.inv(truth) @ moved
        errors.append(np.degrees(np.arcsin(-error[2, 0])))
    return np.array(errors)


def table(title, bins, values, rows):
    print(f"| {title} | steps | " + " | ".join(name for name, _ in rows) + " |")
    print("|---|---|" + "---|" * len(rows))
    for low, high in zip(bins[:-1], bins[1:]):
        chosen = (values >= low) & (values < high)
        n = int(chosen.sum())
        cells = []
        for _, errors in rows:
            e = errors[chosen]
            spread = e.std(ddof=1) / np.sqrt(n) if n > 1 else float("nan")
            cells.append(f"{e.mean():.3f} ± {spread:.3f}")
        print(f"| {low:g}–{high:g} | {n} | " + " | ".join(cells) + " |")
    print()


stretch = slice(FIRST, FIRST + SCANS)
reference = poses(os.path.join(mulran, "poses.txt"), stretch)
estimates = [("lidar-inertial odometry", poses(os.path.join(mulran, "lio_odometry_poses.txt"), stretch))]
if run:
    estimates.append(("sextant odometry", poses(os.path.join(run, "trajectory.kitti.txt"), slice(None))))
rows = [(f"{name} [°]", step_pitch_errors(reference, estimate)) for name, estimate in estimates]
times = np.loadtxt(os.path.join(mulran, "times.txt"))[stretch]
seconds = np.diff(times)
metres = np.linalg.norm(np.diff(reference[:, :3, 3], axis=0), axis=1)
print("Pitch of each step against the reference, mean ± standard error per bin\n")
table("time between keyframes [s]", [0, 0.35, 0.6, 1.5, 30], seconds, rows)
table("step length [m]", [0, 2, 5, 8, 15], metres, rows)
def aligned(estimate):
    """The estimate aligned onto the reference (the ATE's SE(3) alignment), as `sextant eval` aligns it
    before it projects both onto the ground plane."""
    alignment = sextant.metrics.ate(reference, estimate)["alignment"]
    onto = np.eye(4)
    onto[:3, :3] = alignment["rotation"]
    onto[:3, 3] = alignment["translation"]
    return onto @ estimate


flat_reference = sextant.metrics.on_ground_plane(reference)
for name, estimate in estimates:
    drift = sextant.metrics.kitti_drift(reference, estimate)["translation"]
    flat = sextant.metrics.on_ground_plane(aligned(estimate))
    flat_drift = sextant.metrics.kitti_drift(flat_reference, flat)["translation"]
    print(f"{name}: KITTI drift {100 * drift:.2f} %, on the ground plane {100 * flat_drift:.2f} %")
