#!/usr/bin/env python3
"""Right or say so for `sextant match A B` with no options (issue 22): pairs of the shared MulRan
keyframes k and k + d, registered from the identity as `sextant match` does (Python's match(), the
same calls), for every 4th k of the two stretches whose reference holds (0-107 and 116-165) and
d = 1 ... 5 keyframes apart (0.6-36 m). Prints per d: the pairs, the median distance between their
sensors, how many end within 1 m and 5 degrees of the reference, how many end farther and say
trusted (the number that must be 0), the untrusted ones, and the median and largest time per pair;
then every trusted wrong pair. A pair whose reference slips sideways more than 0.5 m between them
is not a car's path and cannot judge at the 1 m bar (keyframes 33-35): it is left out.

  bench/pairs_from_identity.py [path/to/mulran_riverside02] [build/python] [GBS seed]
"""
import math
import os
import sys
import time

import numpy as np

mulran = sys.argv[1] if len(sys.argv) > 1 else "../shared/data/mulran_riverside02"
sys.path.insert(0, sys.argv[2] if len(sys.argv) > 2 else "build/python")
seed = int(sys.argv[3]) if len(sys.argv) > 3 else 1
import sextant  # noqa: E402  (the module built beside the CLI)

STRETCHES = [(0, 107), (116, 165)]


def matrix(row):
    T = np.eye(4)
    T[:3, :] = np.asarray(row, dtype=float).reshape(3, 4)
    return T


poses = [matrix(row) for row in np.loadtxt(os.path.join(mulran, "poses.txt"))]
# The steps k -> k + 1 where the reference slips sideways more than 0.5 m, as no car can
# (sextant.metrics.vehicle_slip, `sextant eval --car-slip 0.5`): 33 -> 34 and 34 -> 35.
SLIPPING = {first + k for first, last in STRETCHES
            for k, slip in enumerate(sextant.metrics.vehicle_slip(np.array(poses[first:last + 1]))["slip"])
            if abs(slip) > 0.5}
scans = {}


def scan(k):
    if k not in scans:
        scans[k] = sextant.read_cloud(os.path.join(mulran, "scans", f"{k:06d}.pcd"))
    return scans[k]


print(f"| keyframes apart | pairs | distance (median) [m] | within 1 m and 5° | trusted and wrong | untrusted "
      f"| seconds per pair (median / largest) |  (GBS seed {seed})")
print("|---|---|---|---|---|---|---|")
trusted_wrong = []
for d in range(1, 6):
    rows = []
    for first, last in STRETCHES:
        for k in range(first, last - d + 1, 4):
            if any(s in SLIPPING for s in range(k, k + d)):
                continue
            truth = np.linalg.inv(poses[k]) @ poses[k + d]  # reference k <- input k + d
            start = time.perf_counter()
            r = sextant.match(scan(k), scan(k + d), seed=seed)
            seconds = time.perf_counter() - start
            error = np.linalg.inv(truth) @ np.asarray(r.T)
            metres = np.linalg.norm(error[:3, 3])
            degrees = math.degrees(math.acos(max(-1.0, min(1.0, (np.trace(error[:3, :3]) - 1) / 2))))
            right = metres <= 1.0 and degrees <= 5.0
            rows.append((np.linalg.norm(truth[:3, 3]), right, r.trusted, seconds))
            if r.trusted and not right:
                trusted_wrong.append(f"{k} -> {k + d}: {np.linalg.norm(truth[:3, 3]):.1f} m apart, "
                                     f"{metres:.2f} m and {degrees:.2f} degrees off, trusted")
    times = [row[3] for row in rows]
    print(f"| {d} | {len(rows)} | {np.median([row[0] for row in rows]):.1f} | {sum(row[1] for row in rows)} "
          f"| **{sum(row[2] and not row[1] for row in rows)}** | {sum(not row[2] for row in rows)} "
          f"| {np.median(times):.3f} / {max(times):.3f} |")
for line in trusted_wrong:
    print(line)
