"""sextant.odometry on recordings: the part chosen by topic, start, duration and every is the one the CLI
runs with --topic, --start, --duration, --every, with the same poses; the shared Ouster MCAP and SICK bag
(skipped without the shared data); bad choices raise."""
import os
import pathlib

import numpy as np
import pytest

import sextant
from conftest import SOURCE, run

SHARED = pathlib.Path(os.environ.get("SEXTANT_SHARED_DATA", SOURCE.parent / "shared" / "data")) / "recordings"


@pytest.fixture(scope="module")
def recording(tmp_path_factory):
    """30 known scans at 10 Hz in an MCAP file, written by the tests' recording tool."""
    tool = os.environ.get("SEXTANT_RECORDING_TOOL")
    if not tool:
        pytest.skip("no recording tool: set SEXTANT_RECORDING_TOOL (ctest sets it)")
    path = tmp_path_factory.mktemp("recording") / "scans.mcap"
    done = run([tool, "write", path, 30, 64])
    assert done.returncode == 0, done.stdout + done.stderr
    return path


def kitti_poses(path):
    rows = np.loadtxt(path, ndmin=2)
    poses = np.tile(np.eye(4), (len(rows), 1, 1))
    poses[:, :3, :] = rows.reshape(-1, 3, 4)
    return poses


def test_the_part_chosen_is_the_clis(recording, sextant_binary, tmp_path):
    r = sextant.odometry(recording, topic="/points", start=1.0, duration=1.0, every=3)
    assert r.scans == 4  # scans 10, 13, 16, 19
    assert r.dataset["format"] == "mcap"
    assert any("4 of its 30 messages, from 1 s for 1 s, every 3rd message" in n for n in r.dataset["notes"])
    done = run([sextant_binary, "odometry", recording, "--topic", "/points", "--start", 1, "--duration", 1,
                "--every", 3, "--no-progress", "--out", tmp_path / "out"])
    assert done.returncode == 0, done.stdout + done.stderr
    np.testing.assert_allclose(r.poses, kitti_poses(tmp_path / "out" / "trajectory.kitti.txt"), atol=1e-8)


def test_bad_choices_raise(recording):
    with pytest.raises(sextant.InputError, match="^every: expected a whole number ≥ 1"):
        sextant.odometry(recording, every=0)
    with pytest.raises(sextant.InputError, match="^start: expected a finite number"):
        sextant.odometry(recording, start=float("nan"))
    with pytest.raises(sextant.InputError, match="holds none of the 30 messages of /points"):
        sextant.odometry(recording, start=100.0)
    with pytest.raises(sextant.InputError, match="no topic '/nothing'"):
        sextant.odometry(recording, topic="/nothing")
    with pytest.raises(sextant.InputError, match="^topic: only for a recording, not the campus"):
        sextant.odometry("campus", topic="/points")
    with pytest.raises(ValueError, match="not of a list"):
        sextant.odometry([np.zeros((10, 3)), np.ones((10, 3))], every=2)


def test_the_ouster_mcap(tmp_path):
    mcap = SHARED / "ouster_os1_mcap" / "os1_ros1.mcap"
    if not mcap.is_file():
        pytest.skip(f"no shared recording at {mcap}")
    r = sextant.odometry(mcap)
    assert r.scans == 2 and r.dataset["format"] == "mcap"
    assert r.points_read == 2 * 64 * 2048
    assert r.dropped_non_finite == 0 and r.dropped_no_return > 100000  # an organised scan's empty cells
    assert r.untrusted == 0


def test_the_sick_bag_needs_a_topic():
    bag = SHARED / "sick_lms1xx_bag" / "rms_1xxx_lms_1xx_movement_off.bag"
    if not bag.is_file():
        pytest.skip(f"no shared recording at {bag}")
    with pytest.raises(sextant.InputError, match=r"3 sensor_msgs/PointCloud2 topics: /cloud \(89 messages\).*"
                                                 r"choose one with topic="):
        sextant.odometry(bag)
    assert sextant.odometry(bag, topic="/cloud", every=10).scans == 9
