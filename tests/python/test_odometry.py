"""sextant.odometry: the same poses and steps as `sextant odometry` on the first keyframes of MulRan
Riverside02 (skipped without the shared data), a folder and the same scans as arrays agree, a
synthetic sequence of known poses is recovered, bad input raises."""
import csv
import json

import numpy as np
import pytest

import sextant
from conftest import run

SCANS = 10


def kitti_poses(path):
    rows = np.loadtxt(path, ndmin=2)
    poses = np.tile(np.eye(4), (len(rows), 1, 1))
    poses[:, :3, :] = rows.reshape(-1, 3, 4)
    return poses


@pytest.fixture(scope="module")
def cli_run(mulran, sextant_binary, tmp_path_factory):
    out = tmp_path_factory.mktemp("odometry")
    done = run([sextant_binary, "odometry", mulran, "--scans", SCANS, "--out", out, "--no-progress"])
    assert done.returncode == 0, done.stdout + done.stderr
    with open(out / "steps.csv", newline="") as f:
        steps = list(csv.DictReader(f))
    return kitti_poses(out / "trajectory.kitti.txt"), steps, out


@pytest.fixture(scope="module")
def python_run(mulran):
    return sextant.odometry(mulran, scans=SCANS)


def test_same_poses_as_cli_on_mulran(cli_run, python_run):
    cli_poses, _, _ = cli_run
    assert python_run.poses.shape == (SCANS, 4, 4)
    assert python_run.guess == "constant_velocity"  # no odometry in the folder: the CLI's default
    # trajectory.kitti.txt holds 9 significant digits
    np.testing.assert_allclose(python_run.poses, cli_poses, rtol=1e-8, atol=1e-8)


def test_same_steps_table_as_cli(cli_run, python_run):
    _, cli_steps, _ = cli_run
    steps = python_run.steps
    assert list(steps) == list(cli_steps[0].keys())  # the columns of steps.csv, in its order
    assert all(len(column) == SCANS - 1 for column in steps.values())
    for name, column in steps.items():
        expected = [row[name] for row in cli_steps]
        if column.dtype.kind in "U":
            assert list(column) == expected, name
        elif column.dtype.kind == "b":
            assert list(column) == [v == "1" for v in expected], name
        else:
            if name == "seconds":
                continue  # timing
            values = np.array([float(v) if v else np.nan for v in expected])
            np.testing.assert_allclose(column.astype(float), values, rtol=1e-7, atol=1e-7, err_msg=name)


def test_ground_truth_and_metrics_of_the_run(python_run, mulran, cli_run):
    truth = kitti_poses(mulran / "poses.txt")[:SCANS]
    np.testing.assert_allclose(python_run.ground_truth, truth, atol=1e-12)
    errors = python_run.steps["error_m"]
    rpe = sextant.metrics.rpe(python_run.ground_truth, python_run.poses)
    # The same errors from the relative poses (steps) and from the chained ones (metrics); they differ
    # in rounding only: poses.txt's rotations are orthonormal to 6 digits, which moves a step of up
    # to 14 m by ~1e-5 m.
    assert rpe["translation_rms"] == pytest.approx(np.sqrt(np.mean(errors**2)), abs=2e-5)
    estimate = json.loads((cli_run[2] / "metrics.json").read_text())["estimate"]
    assert rpe["translation_rms"] == pytest.approx(estimate["rpe_m"], rel=1e-9)
    ate = sextant.metrics.ate(python_run.ground_truth, python_run.poses)
    assert ate["translation_rms"] == pytest.approx(estimate["ate_m"], rel=1e-9)
    assert rpe["translation_rms"] < 0.1  # a few cm per keyframe step on this stretch
    assert python_run.hessians.shape == (SCANS - 1, 6, 6) and python_run.relative.shape == (SCANS - 1, 4, 4)
    np.testing.assert_allclose(python_run.poses[1:], python_run.poses[:-1] @ python_run.relative, atol=1e-9)


def test_arrays_give_the_folders_result(mulran):
    count = 5
    scans = [sextant.read_cloud(path, intensity=True) for path in sorted((mulran / "scans").glob("*.pcd"))[:count]]
    arrays = [np.column_stack([points, intensity]) for points, intensity in scans]
    truth = kitti_poses(mulran / "poses.txt")[:count]
    times = np.loadtxt(mulran / "times.txt")[:count]
    from_arrays = sextant.odometry(arrays, poses=truth, times=times)
    from_folder = sextant.odometry(mulran, scans=count)
    assert from_arrays.dataset["format"] == "arrays" and from_arrays.scans == count
    np.testing.assert_allclose(from_arrays.poses, from_folder.poses, rtol=0, atol=1e-12)


def test_common_view_is_the_default_and_whole_scans_can_be_asked_for(mulran, sextant_binary, tmp_path, python_run):
    """common_view=False registers the whole scans, as the CLI's --whole-scans; the default cuts each
    step's reference to what the input's sensor sees."""
    count = 3
    whole = sextant.odometry(mulran, scans=count, common_view=False)
    done = run([sextant_binary, "odometry", mulran, "--scans", count, "--whole-scans", "--out", tmp_path,
                "--no-progress"])
    assert done.returncode == 0, done.stdout + done.stderr
    np.testing.assert_allclose(whole.poses, kitti_poses(tmp_path / "trajectory.kitti.txt"), rtol=1e-8, atol=1e-8)
    first_scan = len(sextant.read_cloud(sorted((mulran / "scans").glob("*.pcd"))[0]))
    assert whole.steps["reference_points"][0] == first_scan
    assert python_run.steps["reference_points"][0] < first_scan


def test_recovers_a_synthetic_sequence_of_known_poses(data_dir):
    """One real scan seen from five poses 0.6 m and 2° apart: odometry must find those poses."""
    world = sextant.read_cloud(data_dir / "velodyne_pair" / "fast_gicp_251370668.pcd").astype(np.float64)
    poses = np.array([sextant.pose_to_matrix(0.6 * k, 0.05 * k, 0, 0, 0, 2.0 * k, degrees=True) for k in range(5)])
    scans = []
    for pose in poses:
        inverse = np.linalg.inv(pose)  # world → scan frame
        scans.append(world @ inverse[:3, :3].T + inverse[:3, 3])
    result = sextant.odometry(scans, poses=poses, guess="identity", jobs=1)
    assert result.untrusted == 0
    errors = [np.linalg.norm((np.linalg.inv(p) @ e)[:3, 3]) for p, e in zip(poses, result.poses)]
    assert max(errors) < 0.02, errors
    assert np.all(result.steps["error_m"] < 0.01)
    assert list(result.steps["trust"]) == ["ok"] * 4


def test_bad_ranges_and_modes_raise(mulran):
    with pytest.raises(sextant.InputError, match="past the dataset"):
        sextant.odometry(mulran, first=500)
    with pytest.raises(sextant.InputError, match="go past"):
        sextant.odometry(mulran, first=160, scans=10)
    with pytest.raises(sextant.InputError, match="no odometry"):
        sextant.odometry(mulran, guess="odometry", scans=2)
    with pytest.raises(sextant.InputError, match="max_acceleration must be"):
        sextant.odometry(mulran, scans=2, max_acceleration=-1.0)


def test_the_sensor_and_platform_are_measured_or_declared(python_run, mulran):
    assert python_run.sensor == "spinning"  # MulRan's OS1-64 covers most of the azimuth circle
    assert python_run.tolerance_m == pytest.approx(1.0)  # keyframes metres apart: a car's
    declared = sextant.odometry(mulran, scans=3, sensor="solid_state", platform="handheld")
    assert declared.sensor == "solid_state"
    assert declared.tolerance_m == pytest.approx(0.3)
    with pytest.raises(sextant.InputError, match="unknown sensor 'mems'"):
        sextant.odometry(mulran, scans=2, sensor="mems")
    with pytest.raises(sextant.InputError, match="unknown platform 'drone'"):
        sextant.odometry(mulran, scans=2, platform="drone")


def test_points_reading_drops_are_counted(data_dir, tmp_path):
    """Issue 64, class 3: a scan file's NaN rows are dropped, warned about, and counted in the run."""
    cloud = sextant.read_cloud(data_dir / "velodyne_pair" / "fast_gicp_251370668.pcd")
    paths = [tmp_path / "a.csv", tmp_path / "b.csv"]
    np.savetxt(paths[0], cloud, fmt="%.9g", delimiter=",")
    np.savetxt(paths[1], np.vstack([cloud, np.full((40, 3), np.nan)]), fmt="%.9g", delimiter=",")
    with pytest.warns(UserWarning, match="b.csv: 40 of .* points dropped .40 non-finite"):
        run = sextant.odometry(paths)
    assert (run.dropped_non_finite, run.dropped_no_return) == (40, 0)
    assert run.points_read == 2 * len(cloud) + 40
    assert list(run.steps["dropped_non_finite"]) == [40]


def test_bad_input_raises(data_dir, tmp_path):
    cloud = sextant.read_cloud(data_dir / "velodyne_pair" / "fast_gicp_251370668.pcd")
    # Issue 64, class 7: the numbers the CLI refuses, Python refuses with the same words.
    with pytest.raises(ValueError, match=r"jobs: 100000 threads on \d+ cores: at most \d+"):
        sextant.odometry([cloud, cloud], jobs=100000)
    with pytest.raises(sextant.InputError, match="min_range must be a finite number"):
        sextant.odometry([cloud, cloud], min_range=float("inf"))
    with pytest.raises(TypeError):  # a count is not negative (no wrap-around to 2**64 - 1)
        sextant.odometry([cloud, cloud], scans=-1)
    with pytest.raises(sextant.InputError, match="unknown map mode"):
        sextant.odometry([cloud, cloud], map="graph")
    with pytest.raises(sextant.InputError, match="unknown guess mode"):
        sextant.odometry([cloud, cloud], guess="psychic")
    with pytest.raises(FileNotFoundError, match="no such dataset folder"):
        sextant.odometry(tmp_path / "missing")
    with pytest.raises(ValueError, match="poses: 1 entries for 2 scans"):
        sextant.odometry([cloud, cloud], poses=np.eye(4)[None])
    with pytest.raises(ValueError, match="past the dataset"):
        sextant.odometry([cloud, cloud], first=2)
    with pytest.raises(TypeError, match="one array"):
        sextant.odometry(cloud)
    # The scans' times are held to what times.txt is held to: finite, each after the one before.
    with pytest.raises(ValueError, match=r"times\[2\]: expected one finite time"):
        sextant.odometry([cloud] * 5, times=[0, 1, float("nan"), 3, 4])
    with pytest.raises(ValueError, match=r"times\[1\]: the time 0\.000000 s is not after the previous"):
        sextant.odometry([cloud, cloud], times=[0, 0])


def test_view_is_the_clis_page(tmp_path):
    """odometry(..., view=) writes the page `sextant odometry --view` writes: every pose, one entry per
    step with its trust, the ground truth; a missing folder raises before the run."""
    path = tmp_path / "run.html"
    r = sextant.odometry("campus", scans=5, view=path)
    page = path.read_text(encoding="utf-8")
    start = page.index('<script type="application/json" id="sx-data">')
    data = json.loads(page[page.index(">", start) + 1:page.index("</script>", start)])
    assert data["estimate"]["count"] == r.poses.shape[0] == 5
    assert data["steps"]["count"] == len(r.steps["trust"]) == 4
    texts = data["steps"]["texts"]
    assert [texts[i] for i in data["steps"]["trust"]] == list(r.steps["trust"])
    assert data["reference"] is not None and data["map"]["count"] > 0
    with pytest.raises(sextant.InputError, match="does not exist"):
        sextant.odometry("campus", scans=5, view=tmp_path / "missing" / "run.html")


def test_scans_whose_points_carry_time_are_deskewed_unless_asked_not_to(data_dir, tmp_path):
    """Issue 63: PCD files with an Ouster-style `t` field (uint32 ns) are deskewed by default."""
    paths = []
    for name in ("fast_gicp_251370668.pcd", "fast_gicp_251371071.pcd"):
        cloud = sextant.read_cloud(data_dir / "velodyne_pair" / name)
        t = (np.arange(len(cloud)) * (100_000_000 // len(cloud))).astype(np.uint32)  # over 0.1 s
        path = tmp_path / name
        with open(path, "w") as f:
            f.write("VERSION 0.7\nFIELDS x y z t\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\n"
                    f"WIDTH {len(cloud)}\nHEIGHT 1\nPOINTS {len(cloud)}\nDATA ascii\n")
            for p, ns in zip(cloud, t):
                f.write(f"{p[0]:.9g} {p[1]:.9g} {p[2]:.9g} {ns}\n")
        paths.append(path)
    # From no motion (the pair's one step is believed then): its velocity deskews both scans.
    on = sextant.odometry(paths, guess="identity")
    assert on.untrusted == 0
    assert (on.deskew, on.timed_scans, on.deskewed) == ("constant_velocity", 2, 2)
    off = sextant.odometry(paths, guess="identity", deskew=False)
    assert (off.deskew, off.timed_scans, off.deskewed) == ("off", 2, 0)
    assert not np.array_equal(on.poses, off.poses)
    plain = sextant.odometry([data_dir / "velodyne_pair" / "fast_gicp_251370668.pcd",
                              data_dir / "velodyne_pair" / "fast_gicp_251371071.pcd"])
    assert (plain.deskew, plain.timed_scans, plain.deskewed) == ("constant_velocity", 0, 0)
