"""Sextant from Python: read clouds, register pairs, run odometry, score trajectories.

The functions are the C++ library's (the extension sextant._sextant, built with
-DSEXTANT_PYTHON=ON); see python/README.md.

    import sextant
    ref = sextant.read_cloud("data/velodyne_pair/fast_gicp_251370668.pcd")   # N×3 float32
    r = sextant.match(ref, "data/velodyne_pair/fast_gicp_251371071.pcd")
    r.T, r.trust, r.covariance
    run = sextant.odometry("path/to/scans", scans=10)
    sextant.metrics.ate(run.ground_truth, run.poses)
"""
from ._sextant import (  # noqa: F401  (re-exported)
    InputError,
    MatchResult,
    OdometryRun,
    __version__,
    match,
    matrix_to_pose,
    odometry,
    pose_to_matrix,
    read_cloud,
    reads_in_place,
    write_cloud,
)
from . import metrics  # noqa: F401

__all__ = [
    "__version__",
    "InputError",
    "MatchResult",
    "OdometryRun",
    "match",
    "matrix_to_pose",
    "metrics",
    "odometry",
    "pose_to_matrix",
    "read_cloud",
    "reads_in_place",
    "write_cloud",
]
