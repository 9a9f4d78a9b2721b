#!/usr/bin/env python3
"""A guess turned about one axis (issue 62): `sextant match` from the true relative pose turned by 10-30
degrees about the input's own x, y or z axis, on the synthetic campus seen by a spinning lidar from its car
route and by a 70-degree rosette carried on foot (both with exact ground truth), each pair k -> k + 1 for
every 5th k of the first 50 scans. Prints per sensor, axis and angle how many pairs end within 1 degree and
say trusted, and the mean registration time, searched with the wide basin from the guess (`wide_basin: {}`)
and with its tilted starts off (`wide_basin: {tilt_candidates: 0}`: yaw x x/y only).

  bench/tilted_guesses.py [build/app/sextant] [build/python] [output folder]
"""
import os
import subprocess
import sys
import tempfile

import numpy as np

sextant_cli = sys.argv[1] if len(sys.argv) > 1 else "build/app/sextant"
sys.path.insert(0, sys.argv[2] if len(sys.argv) > 2 else "build/python")
out = sys.argv[3] if len(sys.argv) > 3 else tempfile.mkdtemp(prefix="tilted_guesses.")
import sextant  # noqa: E402  (the module built beside the CLI)

SENSORS = {
    "spinning lidar, car": "",
    "rosette, on foot": "trajectory:\n  platform: handheld\n  sensor_height: 1.5\n  scan_period: 0.5\n"
    "  sharp_turn_deg: 10\nsensor:\n  pattern: rosette\n  body_length: 0\n  body_width: 0\n",
}
PAIRS = range(5, 50, 5)
ANGLES = (10, 20, 30)


def quaternion_matrix(x, y, z, w):
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def turned(axis, degrees):
    a = np.radians(degrees)
    c, s = np.cos(a), np.sin(a)
    T = np.eye(4)
    i, j = {"x": (1, 2), "y": (2, 0), "z": (0, 1)}[axis]
    T[i, i], T[i, j], T[j, i], T[j, j] = c, -s, s, c
    return T


def angle_deg(E):
    return np.degrees(np.arccos(np.clip((np.trace(E[:3, :3]) - 1) / 2, -1, 1)))


def dataset(label, yaml_text):
    folder = os.path.join(out, label.split(",")[0].replace(" ", "_"))
    args = [sextant_cli, "synth", "--out", folder, "--scans", "51"]
    if yaml_text:
        config = folder + ".yaml"
        with open(config, "w") as f:
            f.write(yaml_text)
        args += ["--config", config, "--stretch-route-to", "4200"]
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    poses = []
    for line in open(os.path.join(folder, "ground_truth.tum")):
        if line.startswith("#"):
            continue
        v = [float(x) for x in line.split()[1:]]
        T = np.eye(4)
        T[:3, :3] = quaternion_matrix(*v[3:])
        T[:3, 3] = v[:3]
        poses.append(T)
    return folder, poses


print("| sensor | guess turned about | by [°] | recovered (tilted starts) | ms | recovered (none) | ms |")
print("|---|---|---|---|---|---|---|")
for label, yaml_text in SENSORS.items():
    folder, poses = dataset(label, yaml_text)
    clouds = {k: sextant.read_cloud(os.path.join(folder, f"scan{k:03d}.3d")) for k in range(0, 51)}
    for axis in "xyz":
        for degrees in ANGLES:
            cells = []
            for wide_basin in ({}, {"tilt_candidates": 0}):
                recovered, seconds = 0, 0.0
                for k in PAIRS:
                    truth = np.linalg.inv(poses[k]) @ poses[k + 1]
                    r = sextant.match(clouds[k], clouds[k + 1], init=truth @ turned(axis, degrees),
                                      wide_basin=wide_basin)
                    seconds += r.seconds
                    recovered += r.trusted and angle_deg(np.linalg.inv(truth) @ r.T) < 1.0
                cells += [f"{recovered} / {len(PAIRS)}", f"{1000 * seconds / len(PAIRS):.1f}"]
            print(f"| {label} | {axis} | {degrees} | " + " | ".join(cells) + " |")
print(f"(datasets in {out})")
