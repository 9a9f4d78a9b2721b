"""Trajectory metrics over N×4×4 pose arrays: ate, rpe, kitti_drift, wulf, kuemmerle; and
vehicle_slip, whether a reference is a car's path; on_ground_plane, poses without height,
roll or pitch.

The C++ library's eval/trajectory_metrics.hpp (the extension's submodule sextant._sextant.metrics),
importable as ``sextant.metrics`` or ``from sextant.metrics import ate``. Each takes
(reference, estimate) and returns a dict of floats and per-pose error arrays (metres, radians).
"""
from ._sextant import metrics as _metrics

ate = _metrics.ate
rpe = _metrics.rpe
kitti_drift = _metrics.kitti_drift
wulf = _metrics.wulf
kuemmerle = _metrics.kuemmerle
vehicle_slip = _metrics.vehicle_slip
on_ground_plane = _metrics.on_ground_plane

__all__ = ["ate", "rpe", "kitti_drift", "wulf", "kuemmerle", "vehicle_slip", "on_ground_plane"]
