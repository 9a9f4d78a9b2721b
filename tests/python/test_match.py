"""sextant.match: the same result as `sextant match` on the same files and options, the ground truth
of a real pair, a known transform of a cloud against itself, bad input, the GIL, the example."""
import json
import threading
import time

import numpy as np
import pytest

import sextant
from conftest import PYTHON, SOURCE, python_env, run


@pytest.fixture(scope="module")
def pair(data_dir):
    folder = data_dir / "velodyne_pair"
    truth = np.loadtxt(folder / "fast_gicp_relative.txt")
    return folder / "fast_gicp_251370668.pcd", folder / "fast_gicp_251371071.pcd", truth


def cli_match(binary, reference, moving, *options):
    done = run([binary, "match", reference, moving, "--json", *options])
    assert done.returncode in (0, 3), done.stderr  # 3: untrusted, still a result
    return json.loads(done.stdout)


def pose_error(truth, estimate):
    """Translation [m] and rotation [deg] of truth⁻¹ · estimate."""
    E = np.linalg.inv(truth) @ estimate
    R = E[:3, :3]
    sin = np.linalg.norm([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]]) / 2
    return np.linalg.norm(E[:3, 3]), np.degrees(np.arctan2(sin, (np.trace(R) - 1) / 2))


def assert_same_as_cli(result, cli):
    np.testing.assert_allclose(result.T, np.array(cli["transform"]), rtol=0, atol=1e-9)
    assert result.iterations == cli["iterations"]
    assert result.converged == cli["converged"]
    assert result.termination == cli["termination"]
    assert result.trust == cli["trust"] and result.trust_reason == cli["trust_reason"]
    assert result.matched_points == cli["matched_points"] and result.input_points == cli["input_points"]
    assert result.overlap == pytest.approx(cli["overlap"], rel=1e-9)
    assert result.matched_fraction == pytest.approx(cli["matched_fraction"], rel=1e-9)
    assert result.score == pytest.approx(cli["score"], rel=1e-9)
    assert ("wide basin" in result.search) == ("wide basin" in cli["search"])
    if "covariance" in cli:  # `sextant match --json` prints H and H⁻¹ too
        np.testing.assert_allclose(result.H, np.array(cli["hessian"]), rtol=1e-9)
        np.testing.assert_allclose(result.covariance, np.array(cli["covariance"], dtype=float), rtol=1e-8)


def test_same_as_cli_without_init(pair, sextant_binary):
    reference, moving, _ = pair
    result = sextant.match(reference, moving)
    cli = cli_match(sextant_binary, reference, moving)
    assert result.search.startswith("wide basin")  # no guess: the wide basin searched
    assert result.preset == "default" and result.trust == "ok"
    assert_same_as_cli(result, cli)


def test_same_as_cli_with_init_and_options(pair, sextant_binary):
    reference, moving, _ = pair
    init = sextant.pose_to_matrix(0.3, 0.05, 0, 0, 0, 1.5, degrees=True)
    result = sextant.match(sextant.read_cloud(reference), sextant.read_cloud(moving), init=init, seed=5,
                           sampling="random")
    cli = cli_match(sextant_binary, reference, moving, "--init", "0.3,0.05,0,0,0,1.5", "--seed", "5",
                    "--sampling", "random")
    assert result.search.startswith("from the guess")
    assert_same_as_cli(result, cli)


def test_same_as_cli_when_the_wide_basin_recovers_a_bad_guess(pair, sextant_binary):
    reference, moving, truth = pair
    result = sextant.match(reference, moving, init=sextant.pose_to_matrix(0, 0, 0, 0, 0, 40, degrees=True))
    cli = cli_match(sextant_binary, reference, moving, "--init", "0,0,0,0,0,40")
    assert result.search == "from the guess, low_overlap: recovered by the wide basin"
    assert_same_as_cli(result, cli)
    assert pose_error(truth, result.T)[0] < 0.05
    # the same guess as a 4×4 matrix on the command line (16 numbers, all digits)
    matrix = ",".join(repr(v) for v in sextant.pose_to_matrix(0, 0, 0, 0, 0, 40, degrees=True).ravel())
    assert_same_as_cli(result, cli_match(sextant_binary, reference, moving, "--init", matrix))


def test_same_as_cli_for_icp_and_another_preset(pair, sextant_binary):
    reference, moving, _ = pair
    init = sextant.pose_to_matrix(0.3, 0, 0, 0, 0, 0)
    icp = sextant.match(reference, moving, init=init, method="icp_p2l")
    assert_same_as_cli(icp, cli_match(sextant_binary, reference, moving, "--init", "0.3,0,0,0,0,0",
                                      "--method", "icp_p2l"))
    assert icp.preset == ""
    outdoor = sextant.match(reference, moving, preset="outdoor", solver="newton")
    assert_same_as_cli(outdoor, cli_match(sextant_binary, reference, moving, "--preset", "outdoor",
                                          "--solver", "newton"))


def test_recovers_the_ground_truth_of_a_real_pair(pair):
    reference, moving, truth = pair
    result = sextant.match(reference, moving)
    metres, degrees = pose_error(truth, result.T)
    assert result.trusted and result.converged
    assert metres < 0.05 and degrees < 0.6, (metres, degrees)
    assert np.isfinite(result.covariance).all()
    assert np.all(np.linalg.eigvalsh(result.covariance) > 0)
    np.testing.assert_allclose(result.covariance @ result.H, np.eye(6), atol=1e-6)  # R = H⁻¹
    np.testing.assert_allclose(sextant.pose_to_matrix(*result.pose), result.T, atol=1e-12)


def test_arrays_of_either_dtype_and_paths_give_the_same_result(pair):
    reference, moving, _ = pair
    ref32, in32 = sextant.read_cloud(reference), sextant.read_cloud(moving)
    by_path = sextant.match(reference, moving)
    by_float32 = sextant.match(ref32, in32)
    by_float64 = sextant.match(ref32.astype(np.float64), np.asfortranarray(in32.astype(np.float64)))
    strided = np.zeros((len(in32), 5), dtype=np.float32)
    strided[:, 1:4] = in32
    by_view = sextant.match(ref32, strided[:, 1:4])  # a non-contiguous view
    for other in (by_float32, by_float64, by_view):
        np.testing.assert_array_equal(other.T, by_path.T)


def test_clouds_far_from_their_origin_are_registered_about_the_reference(pair):
    reference, moving, truth = pair
    home = sextant.match(reference, moving)
    np.testing.assert_array_equal(home.centre, [0, 0, 0])
    offset = np.array([0.0, 300.0, 0.0])
    away = np.eye(4)
    away[:3, 3] = offset
    far = sextant.match(sextant.read_cloud(reference) + offset, sextant.read_cloud(moving) + offset)
    assert far.trusted, far.trust_reason
    assert 0 < np.linalg.norm(far.centre - offset) < 60  # the middle of the reference's box
    metres, degrees = pose_error(truth, np.linalg.inv(away) @ far.T @ away)
    assert metres < 0.05 and degrees < 0.7


def test_the_library_layout_is_read_in_place_and_others_are_copied(pair):
    reference, _, _ = pair
    points = sextant.read_cloud(reference)
    assert sextant.reads_in_place(points)
    assert sextant.reads_in_place(np.ascontiguousarray(points[10:]))
    assert not sextant.reads_in_place(points.astype(np.float64))
    assert not sextant.reads_in_place(np.asfortranarray(points))
    assert not sextant.reads_in_place(points[::2])  # rows 24 bytes apart
    assert not sextant.reads_in_place(np.column_stack([points, points[:, :1]]))  # N×4
    # Read in place, the array is left as it was and a NaN row is still refused by its index.
    before = points.copy()
    sextant.match(points, points, init=np.eye(4))
    np.testing.assert_array_equal(points, before)
    points[7, 1] = np.nan
    with pytest.raises(ValueError, match="row 7 is not finite"):
        sextant.match(points, before)


def test_recovers_a_known_transform_of_a_cloud_against_itself(pair):
    reference_path, _, _ = pair
    points, intensity = sextant.read_cloud(reference_path, intensity=True)
    known = sextant.pose_to_matrix(0.8, -0.4, 0.05, 0.5, -0.3, 6.0, degrees=True)
    # input = known⁻¹ · reference, so that known maps the input back onto the reference
    inverse = np.linalg.inv(known)
    moved = (points.astype(np.float64) @ inverse[:3, :3].T + inverse[:3, 3]).astype(np.float32)
    with_intensity = np.column_stack([moved, intensity])  # N×4
    for init in (None, sextant.pose_to_matrix(0.5, 0, 0, 0, 0, 0)):
        result = sextant.match(points, with_intensity, init=init)
        metres, degrees = pose_error(known, result.T)
        assert result.trusted
        assert metres < 0.01 and degrees < 0.05, (init is None, metres, degrees)


def test_bad_input_raises():
    cloud = np.random.default_rng(1).uniform(-10, 10, size=(2000, 3))
    with pytest.raises(ValueError, match="N×3"):
        sextant.match(cloud[:, :2], cloud)
    with pytest.raises(ValueError, match="no points"):
        sextant.match(cloud, cloud[:0])
    bad = cloud.copy()
    bad[17, 1] = np.inf
    with pytest.raises(ValueError, match="input: row 17"):
        sextant.match(cloud, bad)
    with pytest.raises(ValueError, match="rigid"):
        sextant.match(cloud, cloud, init=np.diag([1.0, 2.0, 1.0, 1.0]))
    with pytest.raises(ValueError, match="4×4"):
        sextant.match(cloud, cloud, init=np.eye(3))
    with pytest.raises(sextant.InputError, match="presets are settings of mlndt"):
        sextant.match(cloud, cloud, method="icp_p2p", preset="outdoor")
    with pytest.raises(sextant.InputError, match="no_such_key"):
        sextant.match(cloud, cloud, no_such_key=3)
    with pytest.raises(sextant.InputError, match="preset"):
        sextant.match(cloud, cloud, preset="nonsense")
    with pytest.raises(ValueError, match="unknown matcher .nomatcher."):
        sextant.match(cloud, cloud, method="nomatcher")
    with pytest.raises(TypeError):
        sextant.match(cloud, cloud, wide_basin="yes")


def test_no_wide_basin_registers_from_the_identity(pair, sextant_binary):
    reference, moving, _ = pair
    result = sextant.match(reference, moving, wide_basin=False)
    assert result.search == "from the guess"
    assert_same_as_cli(result, cli_match(sextant_binary, reference, moving, "--no-wide-basin"))


def test_the_gil_is_released_while_registering(pair):
    reference, moving, _ = pair
    ref, inp = sextant.read_cloud(reference), sextant.read_cloud(moving)
    durations = []
    finished = threading.Event()

    def register():
        for _ in range(3):
            start = time.perf_counter()
            sextant.match(ref, inp, method="icp_p2l", init=np.eye(4))  # mostly the k-d tree and normals, in C++
            durations.append(time.perf_counter() - start)
        finished.set()

    worker = threading.Thread(target=register)
    worker.start()
    longest_stall, last = 0.0, time.perf_counter()
    while not finished.is_set():  # Python keeps running here unless match holds the GIL
        now = time.perf_counter()
        longest_stall, last = max(longest_stall, now - last), now
    worker.join()
    # With the GIL held, this loop would stall for a whole registration at least once.
    assert longest_stall < 0.5 * min(durations), (longest_stall, durations)


def test_the_example_script_registers_the_pair():
    script = SOURCE / "python" / "examples" / "register_pair.py"
    done = run([PYTHON, script], env=python_env())
    assert done.returncode == 0, done.stdout + done.stderr
    assert "trust: ok" in done.stdout
    line = next(l for l in done.stdout.splitlines() if l.startswith("error against"))
    assert float(line.split(": ")[1].split(" cm")[0]) < 5.0
