"""sextant.metrics against values computed by hand: a constant offset, a constant body rotation, a
scaled path (ATE with each alignment, RPE, KITTI drift, Wulf, Kümmerle), and bad input raising."""
import numpy as np
import pytest

import sextant
from sextant import metrics


def straight_path(count, step=1.0, yaw_deg=0.0):
    """Poses every `step` metres along x, all with the same yaw."""
    return np.array([sextant.pose_to_matrix(step * k, 0, 0, 0, 0, yaw_deg, degrees=True) for k in range(count)])


def test_rpe_signed_mean_tells_a_shared_bias_from_noise():
    pitch = np.radians(0.1)
    reference = straight_path(21)
    for alternating in (False, True):
        estimate = [np.eye(4)]
        for k in range(20):
            sign = -1.0 if alternating and k % 2 else 1.0
            step = sextant.pose_to_matrix(1.0, 0, 0, 0, sign * pitch, 0)
            estimate.append(estimate[-1] @ step)
        rpe = metrics.rpe(reference, np.array(estimate))
        assert rpe["rotation"]["mean"] == pytest.approx(pitch, abs=1e-12)  # the same unsigned error
        expected = 0.0 if alternating else pitch
        np.testing.assert_allclose(rpe["mean_rotation_vector"], [0.0, expected, 0.0], atol=1e-12)
        assert rpe["rotation_vector_standard_error"][1] == pytest.approx(
            pitch / np.sqrt(19) if alternating else 0.0, abs=1e-12)
        np.testing.assert_allclose(rpe["mean_translation"], 0.0, atol=1e-12)


def winding_path(count):
    """A path that turns and climbs, so that positions fix a rigid alignment."""
    return np.array([sextant.pose_to_matrix(3 * np.cos(k / 5), 2 * np.sin(k / 4), 0.1 * k, 0.02 * k, -0.01 * k,
                                            0.1 * k) for k in range(count)])


def test_constant_translation_offset():
    reference = winding_path(30)
    estimate = reference.copy()
    estimate[:, :3, 3] += [0.3, -0.4, 0.0]  # 0.5 m off everywhere, same orientation
    none = metrics.ate(reference, estimate, alignment="none")
    assert none["translation_rms"] == pytest.approx(0.5, abs=1e-12)
    assert none["translation"]["max"] == pytest.approx(0.5, abs=1e-12)
    assert none["rotation_rms"] == pytest.approx(0.0, abs=1e-7)  # the library's acos: ~1e-8 rad resolution
    np.testing.assert_allclose(none["translation_errors"], 0.5, atol=1e-12)
    se3 = metrics.ate(reference, estimate)  # se3 by default: the offset is aligned away
    assert se3["translation_rms"] == pytest.approx(0.0, abs=1e-9)
    np.testing.assert_allclose(se3["alignment"]["translation"], [-0.3, 0.4, 0.0], atol=1e-9)
    np.testing.assert_allclose(se3["alignment"]["rotation"], np.eye(3), atol=1e-9)
    wulf = metrics.wulf(reference, estimate)
    assert wulf["position_rms"] == pytest.approx(0.5, abs=1e-12)
    assert wulf["orientation_rms"] == pytest.approx(0.0, abs=1e-12)
    # relative metrics do not see a constant offset of the whole trajectory... in the world frame only
    # when orientations are equal: then x_i⁻¹ x_j is unchanged
    assert metrics.kuemmerle(reference, estimate)["translation_rms"] == pytest.approx(0.0, abs=1e-12)
    assert metrics.rpe(reference, estimate)["translation_rms"] == pytest.approx(0.0, abs=1e-12)


def test_a_rigidly_moved_trajectory_aligns_away():
    reference = winding_path(25)
    G = sextant.pose_to_matrix(5.0, -2.0, 1.0, 0.1, 0.2, 1.0)
    estimate = G @ reference  # the same trajectory in another world frame
    for alignment in ("se3", "sim3", "origin"):
        result = metrics.ate(reference, estimate, alignment=alignment)
        assert result["translation_rms"] == pytest.approx(0.0, abs=1e-9), alignment
        assert result["rotation_rms"] == pytest.approx(0.0, abs=1e-7), alignment
    origin = metrics.ate(reference, estimate, alignment="origin")
    np.testing.assert_allclose(origin["alignment"]["rotation"], np.linalg.inv(G)[:3, :3], atol=1e-12)
    # no alignment: each pose is off by ‖G·p − p‖
    offsets = np.linalg.norm((estimate - reference)[:, :3, 3], axis=1)
    none = metrics.ate(reference, estimate, alignment="none")
    np.testing.assert_allclose(none["translation_errors"], offsets, atol=1e-12)


def test_constant_body_rotation():
    theta = np.radians(3.0)
    reference = straight_path(20)  # 1 m steps along x, no rotation
    estimate = reference @ sextant.pose_to_matrix(0, 0, 0, 0, 0, theta)  # every pose yawed by theta
    wulf = metrics.wulf(reference, estimate)
    assert wulf["position_rms"] == pytest.approx(0.0, abs=1e-12)
    assert wulf["orientation_rms"] == pytest.approx(theta, abs=1e-12)
    # E = Δ⁻¹ Rz⁻¹ Δ Rz with Δ a 1 m step: ‖t(E)‖ = ‖Rzᵀ·d − d‖ = 2·sin(θ/2), angle 0
    rpe = metrics.rpe(reference, estimate)
    assert rpe["translation_rms"] == pytest.approx(2 * np.sin(theta / 2), abs=1e-12)
    assert rpe["rotation_rms"] == pytest.approx(0.0, abs=1e-7)
    assert rpe["pairs"].tolist() == [[k, k + 1] for k in range(19)]
    kuemmerle = metrics.kuemmerle(reference, estimate)
    assert kuemmerle["translation_rms"] == pytest.approx(2 * np.sin(theta / 2), abs=1e-12)
    ate = metrics.ate(reference, estimate, alignment="none")
    assert ate["rotation_rms"] == pytest.approx(theta, abs=1e-12)


def test_scaled_path():
    reference = straight_path(11, step=1.0)
    estimate = straight_path(11, step=1.1)  # 10 % too long
    # without alignment the error grows 0.1 m per pose: rms of 0.1·k for k = 0 … 10
    expected = np.sqrt(np.mean((0.1 * np.arange(11)) ** 2))
    assert metrics.ate(reference, estimate, alignment="none")["translation_rms"] == pytest.approx(expected, abs=1e-12)
    sim3 = metrics.ate(reference, estimate, alignment="sim3")
    assert sim3["translation_rms"] == pytest.approx(0.0, abs=1e-9)
    assert sim3["alignment"]["scale"] == pytest.approx(1 / 1.1, abs=1e-12)
    assert metrics.rpe(reference, estimate)["translation_rms"] == pytest.approx(0.1, abs=1e-12)
    assert metrics.rpe(reference, estimate, delta=2)["translation_rms"] == pytest.approx(0.2, abs=1e-12)
    rpe = metrics.rpe(reference, estimate)
    assert rpe["scale_error"] == pytest.approx(0.1, abs=1e-12)  # every motion 10 % long
    assert rpe["scale_standard_error"] == pytest.approx(0.0, abs=1e-12)
    assert rpe["scale_pairs"] == 10
    assert metrics.kuemmerle(reference, estimate)["translation_rms"] == pytest.approx(0.1, abs=1e-12)
    # Kümmerle over chosen relations, one with its reference motion given (reference may be None)
    given = metrics.kuemmerle(None, estimate, relations=[(0, 10, sextant.pose_to_matrix(10, 0, 0, 0, 0, 0))])
    np.testing.assert_allclose(given["translation_errors"], [1.0], atol=1e-12)


def test_kitti_drift_of_a_one_percent_long_path():
    reference = straight_path(250)  # 0 … 249 m, 1 m apart
    estimate = straight_path(250, step=1.01)
    drift = metrics.kitti_drift(reference, estimate)
    # a segment of length L from frame i ends at the first frame more than L further: i + L + 1, where the
    # estimate is 0.01·(L + 1) m too long. L = 100: first frames 0, 10, …, 140 (15); L = 200: 0 … 40 (5).
    assert drift["segments"] == 20
    assert [(d["length"], d["segments"]) for d in drift["per_length"][:3]] == [(100, 15), (200, 5), (300, 0)]
    assert drift["per_length"][0]["translation"] == pytest.approx(0.01 * 101 / 100, abs=1e-12)
    assert np.isnan(drift["per_length"][2]["translation"])
    assert drift["translation"] == pytest.approx((15 * 0.01 * 101 / 100 + 5 * 0.01 * 201 / 200) / 20, abs=1e-12)
    assert drift["rotation"] == pytest.approx(0.0, abs=1e-12)
    with pytest.raises(ValueError, match="shorter than the shortest segment"):
        metrics.kitti_drift(reference[:50], estimate[:50])


def test_bad_input_raises():
    reference = straight_path(5)
    # Issue 64, class 7: a delta of 1e300 frames looped for ever (its step wrapped around).
    with pytest.raises(ValueError, match="delta in frames must be at most 2"):
        metrics.rpe(reference, reference, delta=1e300)
    with pytest.raises(ValueError, match="tolerance must be a finite number"):
        metrics.rpe(reference, reference, delta=1.0, unit="meters", tolerance=float("inf"))
    with pytest.raises(ValueError, match="estimate has 4 poses, reference 5"):
        metrics.ate(reference, reference[:4])
    with pytest.raises(ValueError, match="at least 2 poses"):
        metrics.ate(reference[:1], reference[:1])
    broken = reference.copy()
    broken[2, 0, 3] = np.nan
    for metric in (metrics.ate, metrics.rpe, metrics.kitti_drift, metrics.wulf, metrics.kuemmerle):
        with pytest.raises(ValueError, match="finite"):
            metric(reference, broken)
        with pytest.raises(ValueError, match="finite"):
            metric(broken, reference)
    with pytest.raises(ValueError, match="N×4×4"):
        metrics.wulf(reference[:, :3], reference[:, :3])
    with pytest.raises(ValueError, match="alignment"):
        metrics.ate(reference, reference, alignment="affine")
    with pytest.raises(ValueError, match="unit"):
        metrics.rpe(reference, reference, unit="furlongs")


def test_vehicle_slip_finds_the_step_no_car_drives():
    """A car on arcs of changing curvature, its sensor mounted turned 0.3 rad against its axis: every
    step slips 0; the path moved 1.2 m to the left from step 5 on makes step 5 slip +1.2 m."""
    mounting, chord = -0.3, 4.0
    heading, position, poses = 0.0, np.zeros(2), []
    for k in range(12):
        poses.append(sextant.pose_to_matrix(position[0], position[1], 0, 0, 0, heading - mounting))
        turn = 0.08 * np.sin(k / 2)
        position = position + chord * np.array([np.cos(heading + turn / 2), np.sin(heading + turn / 2)])
        heading += turn
    poses = np.array(poses)
    arcs = metrics.vehicle_slip(poses)
    assert arcs["mounting"] == pytest.approx(mounting, abs=1e-9)
    np.testing.assert_allclose(arcs["slip"], 0.0, atol=1e-9)

    moved = poses.copy()
    step_heading = np.arctan2(poses[6, 1, 3] - poses[5, 1, 3], poses[6, 0, 3] - poses[5, 0, 3])
    moved[6:, :2, 3] += 1.2 * np.array([-np.sin(step_heading), np.cos(step_heading)])  # to the left
    slipped = metrics.vehicle_slip(moved)
    assert slipped["slip"][5] == pytest.approx(1.2, abs=1e-9)
    np.testing.assert_allclose(np.delete(slipped["slip"], 5), 0.0, atol=1e-9)
    with pytest.raises(ValueError):
        metrics.vehicle_slip(poses, min_chord=0.0)


def test_on_ground_plane_keeps_x_y_and_heading():
    pose = sextant.pose_to_matrix(4.0, -2.5, 3.0, 0.2, -0.1, 0.7)
    flat = metrics.on_ground_plane(np.array([pose, np.eye(4)]))
    assert flat.shape == (2, 4, 4)
    np.testing.assert_allclose(flat[0, :3, 3], [4.0, -2.5, 0.0], atol=1e-15)
    heading = np.arctan2(pose[1, 0], pose[0, 0])
    np.testing.assert_allclose(flat[0], sextant.pose_to_matrix(4.0, -2.5, 0, 0, 0, heading), atol=1e-15)
    np.testing.assert_allclose(flat[1], np.eye(4), atol=0)
