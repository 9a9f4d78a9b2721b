"""sextant.odometry(build_map=True): the run's map as arrays, the same RunMap as `sextant odometry
--map-out` (the CLI's file read back is the same map), one scan's map is the voxel centroids NumPy
computes, bad map arguments raise."""
import json

import numpy as np
import pytest

import sextant
from conftest import run


def voxel_centroids(points, intensity, voxel):
    """One row per occupied voxel, the centroid of its points and their mean intensity, in the order the
    voxels are first hit: what the map of one scan must be."""
    keys = np.floor(points * (1.0 / voxel)).astype(np.int64)
    _, first, inverse = np.unique(keys, axis=0, return_index=True, return_inverse=True)
    inverse = inverse.ravel()
    counts = np.bincount(inverse)
    centroids = np.stack([np.bincount(inverse, weights=points[:, a]) for a in range(3)], axis=1) / counts[:, None]
    means = np.bincount(inverse, weights=intensity) / counts
    order = np.argsort(first)
    return centroids[order], means[order]


def test_one_scans_map_is_the_voxel_centroids_of_its_points(data_dir):
    points, intensity = sextant.read_cloud(data_dir / "velodyne_pair" / "fast_gicp_251370668.pcd", intensity=True)
    pose = sextant.pose_to_matrix(3.0, -2.0, 0.5, 0, 0, 30.0, degrees=True)  # where the scan stands
    result = sextant.odometry([np.column_stack([points, intensity])], poses=pose[None], build_map=True,
                              map_voxel=0.5)
    world = points.astype(np.float64) @ pose[:3, :3].T + pose[:3, 3]
    centroids, means = voxel_centroids(world, intensity.astype(np.float64), 0.5)
    assert result.map_voxel == 0.5
    assert result.map_points.dtype == np.float32 and result.map_points.shape == (len(centroids), 3)
    assert len(centroids) < len(points) / 2  # one point per voxel
    np.testing.assert_allclose(result.map_points, centroids, rtol=0, atol=1e-4)
    assert result.map_intensity.dtype == np.float32
    np.testing.assert_allclose(result.map_intensity, means, rtol=1e-5)


def test_the_map_is_the_clis_map_file(mulran, sextant_binary, tmp_path):
    count = 10
    done = run([sextant_binary, "odometry", mulran, "--scans", count, "--out", tmp_path / "out", "--map-out",
                tmp_path / "map.pcd", "--no-progress"])
    assert done.returncode == 0, done.stdout + done.stderr
    points, intensity = sextant.read_cloud(tmp_path / "map.pcd", intensity=True)
    result = sextant.odometry(mulran, scans=count, build_map=True)
    provenance = json.loads((tmp_path / "out" / "provenance.json").read_text())["map_out"]
    assert result.map_voxel == provenance["voxel_m"]
    assert f"map:      {len(points)} points (voxel {result.map_voxel:g} m)" in done.stdout
    np.testing.assert_array_equal(result.map_points, points)
    np.testing.assert_array_equal(result.map_intensity, intensity)
    assert result.map_scans_left_out == 0


def test_no_map_unless_asked_and_bad_map_arguments_raise(data_dir):
    cloud = sextant.read_cloud(data_dir / "velodyne_pair" / "fast_gicp_251370668.pcd")
    plain = sextant.odometry([cloud])
    assert plain.map_points is None and plain.map_intensity is None and plain.map_voxel is None
    mapped = sextant.odometry([cloud], build_map=True)
    assert mapped.map_intensity is None  # the array had no intensity
    assert mapped.map_voxel > 0 and len(mapped.map_points) > 0
    with pytest.raises(ValueError, match="map_voxel: a map's voxel needs build_map=True"):
        sextant.odometry([cloud], map_voxel=0.2)
    with pytest.raises(ValueError, match="map_trusted_only: needs build_map=True"):
        sextant.odometry([cloud], map_trusted_only=True)
    for bad in (0.0, -1.0, float("inf"), float("nan")):
        with pytest.raises(sextant.InputError, match="map_voxel must be a finite number > 0"):
            sextant.odometry([cloud], build_map=True, map_voxel=bad)
