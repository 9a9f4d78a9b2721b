"""sextant.read_cloud / write_cloud and the pose helpers: known answers from files written here or
parsed by hand, the library's error messages, and no copy on the way out."""
import re

import numpy as np
import pytest

import sextant


def parse_binary_pcd(path):
    """x y z intensity of a `DATA binary` PCD with four float32 fields, parsed without the library."""
    blob = path.read_bytes()
    header, _, body = blob.partition(b"DATA binary\n")
    fields = dict(line.split(" ", 1) for line in header.decode().splitlines() if not line.startswith("#"))
    assert fields["FIELDS"] == "x y z intensity" and fields["TYPE"] == "F F F F"
    count = int(fields["POINTS"])
    table = np.frombuffer(body[: count * 16], dtype="<f4").reshape(count, 4)
    return table[:, :3], table[:, 3]


def test_text_cloud_reads_back_the_points_written(tmp_path):
    rng = np.random.default_rng(7)
    points = (rng.normal(size=(500, 3)) * 20).astype(np.float32)
    path = tmp_path / "cloud.csv"
    np.savetxt(path, points, fmt="%.9g", delimiter=",")  # 9 digits: every float32 exactly
    read = sextant.read_cloud(path)
    assert read.dtype == np.float32 and read.shape == (500, 3)
    np.testing.assert_array_equal(read, points)


def test_pcd_reads_the_files_points_and_intensity(data_dir):
    path = data_dir / "velodyne_pair" / "fast_gicp_251370668.pcd"
    xyz, intensity = parse_binary_pcd(path)
    points, read_intensity = sextant.read_cloud(path, intensity=True)
    assert points.shape == (69088, 3)
    np.testing.assert_array_equal(points, xyz)
    np.testing.assert_array_equal(read_intensity, intensity)
    np.testing.assert_array_equal(sextant.read_cloud(str(path)), xyz)  # str or PathLike


def test_no_intensity_is_none_and_the_return_type_depends_on_the_argument_only(tmp_path):
    path = tmp_path / "three.xyz"
    path.write_text("1 2 3\n4 5 6\n")
    points, intensity = sextant.read_cloud(path, intensity=True)
    assert intensity is None
    np.testing.assert_array_equal(points, [[1, 2, 3], [4, 5, 6]])
    assert isinstance(sextant.read_cloud(path), np.ndarray)


def test_read_cloud_hands_over_the_library_memory_without_a_copy(data_dir):
    points, intensity = sextant.read_cloud(data_dir / "velodyne_pair" / "fast_gicp_251370668.pcd", intensity=True)
    assert not points.flags.owndata and points.flags.c_contiguous
    assert type(points.base).__name__ == "PyCapsule"
    assert points.base is intensity.base  # one cloud owns both


def test_a_malformed_file_raises_the_library_message_with_file_and_line(tmp_path):
    path = tmp_path / "bad.xyz"
    path.write_text("1 2 3\n4 five 6\n")
    with pytest.raises(sextant.InputError) as caught:
        sextant.read_cloud(path)
    error = caught.value
    assert isinstance(error, ValueError)
    assert error.file == str(path) and error.where == "line 2"
    assert "five" in error.problem
    assert str(error) == f"{path}:line 2: {error.problem}"


def test_missing_empty_and_unknown_files_raise(tmp_path):
    # Issue 64, class 6: what the system refuses is the matching OSError, with the CLI's problem.
    with pytest.raises(FileNotFoundError, match="cannot open") as caught:
        sextant.read_cloud(tmp_path / "missing.pcd")
    assert caught.value.filename == str(tmp_path / "missing.pcd")
    (tmp_path / "empty.xyz").write_text("")
    with pytest.raises(sextant.InputError):
        sextant.read_cloud(tmp_path / "empty.xyz")
    (tmp_path / "cloud.unknown").write_text("1 2 3\n")
    with pytest.raises(sextant.InputError, match=re.escape("unknown")):
        sextant.read_cloud(tmp_path / "cloud.unknown")


def test_write_cloud_round_trips_float64_with_intensity(tmp_path):
    rng = np.random.default_rng(3)
    points = rng.uniform(-50, 50, size=(1000, 3))
    intensity = rng.uniform(0, 255, size=1000)
    path = tmp_path / "out.pcd"
    sextant.write_cloud(path, points, intensity=intensity)
    read, read_intensity = sextant.read_cloud(path, intensity=True)
    np.testing.assert_array_equal(read, points.astype(np.float32))
    np.testing.assert_array_equal(read_intensity, intensity.astype(np.float32))


def test_an_output_the_system_refuses_is_an_oserror_naming_the_file(tmp_path):
    (tmp_path / "file").write_text("a file, not a folder\n")
    for name in ["a.pcd", "a.ply", "a.3d", "a.bin"]:
        target = tmp_path / "file" / name
        with pytest.raises(OSError) as caught:
            sextant.write_cloud(target, np.zeros((3, 3)))
        assert caught.value.filename == str(target), name
        assert "PCL" not in str(caught.value) and "pcl::" not in str(caught.value)
    with pytest.raises(NotADirectoryError, match="is a file, expected a dataset folder"):
        sextant.odometry(tmp_path / "file")
    with pytest.raises(FileNotFoundError, match="no such dataset folder"):
        sextant.odometry(tmp_path / "missing")


def test_write_cloud_rejects_bad_arrays(tmp_path):
    with pytest.raises(ValueError, match="N×3"):
        sextant.write_cloud(tmp_path / "a.pcd", np.zeros((4, 2)))
    with pytest.raises(ValueError, match="float32 or float64"):
        sextant.write_cloud(tmp_path / "a.pcd", np.zeros((4, 3), dtype=np.int32))
    with pytest.raises(ValueError, match="row 2"):
        sextant.write_cloud(tmp_path / "a.pcd", np.array([[0, 0, 0], [1, 1, 1], [np.nan, 0, 0]]))


def test_dropped_points_are_counted_in_a_warning(tmp_path):
    """Issue 64, class 3: reading drops NaN rows and a .3d writer cannot keep points beyond 32.75 m;
    both say so in a UserWarning that names the file and counts them."""
    path = tmp_path / "half.csv"
    path.write_text("1,2,3\nnan,2,3\n4,5,6\nnan,nan,nan\n")
    with pytest.warns(UserWarning, match=re.escape(f"{path}: 2 of 4 points dropped (2 non-finite, 0 no-return)")):
        assert sextant.read_cloud(path).shape == (2, 3)
    far = np.array([[1, 2, 3], [40, 0, 0], [0, 0, 32.8]], dtype=np.float32)
    with pytest.warns(UserWarning, match="2 of 3 points written to .*far.3d lie at or beyond 32.75 m"):
        sextant.write_cloud(tmp_path / "far.3d", far)
    with pytest.warns(UserWarning, match="2 of 3 points dropped .0 non-finite, 2 no-return."):
        assert sextant.read_cloud(tmp_path / "far.3d").shape == (1, 3)
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")  # nothing to say: no warning
        sextant.write_cloud(tmp_path / "far.pcd", far)
        assert sextant.read_cloud(tmp_path / "far.pcd").shape == (3, 3)


def test_pose_to_matrix_is_rx_ry_rz_and_inverts():
    a, b, g = 0.1, -0.2, 0.3
    rx = np.array([[1, 0, 0], [0, np.cos(a), -np.sin(a)], [0, np.sin(a), np.cos(a)]])
    ry = np.array([[np.cos(b), 0, np.sin(b)], [0, 1, 0], [-np.sin(b), 0, np.cos(b)]])
    rz = np.array([[np.cos(g), -np.sin(g), 0], [np.sin(g), np.cos(g), 0], [0, 0, 1]])
    T = sextant.pose_to_matrix(1, 2, 3, a, b, g)
    np.testing.assert_allclose(T[:3, :3], rx @ ry @ rz, atol=1e-15)
    np.testing.assert_array_equal(T[:3, 3], [1, 2, 3])
    np.testing.assert_allclose(sextant.matrix_to_pose(T), (1, 2, 3, a, b, g), atol=1e-14)
    np.testing.assert_allclose(sextant.pose_to_matrix(0, 0, 0, 0, 0, 90, degrees=True)[:2, :2], [[0, -1], [1, 0]],
                               atol=1e-15)
    with pytest.raises(ValueError, match="rigid"):
        sextant.matrix_to_pose(np.diag([2.0, 1, 1, 1]))
