"""The glTF export played by a real viewer: three.js (npm `three`, pinned in tools/npm) in headless Chromium
(Debian's `chromium`), driven by tools/gltf_viewer/sample.js. What three.js interpolates between the keys is
compared with tumble's own simulation at the same times: the independent check of the export's motion.

Both are installed by `scripts/setup.sh test`; without them this test FAILS. Its screenshots are kept in
<build>/python/gltf_viewer/ to look at."""
import json
import os
import pathlib
import shutil
import subprocess

import numpy as np
import pytest

import tumble
from conftest import SCENES, SOURCE_DIR

SAMPLE = SOURCE_DIR / "tools/gltf_viewer/sample.js"
# glTF's axes from tumble's (the documented y-up turn): x stays, z becomes +y, y becomes -z.
Y_UP = np.array([[1, 0, 0], [0, 0, 1], [0, -1, 0]], dtype=float)
SLACK = 2e-5  # rad: float32 keys and three.js's float slerp, beyond the export's own tolerance


def play(path, nodes, times, shots=(), png_dir=None):
    """three.js's world pose of each node at each time: {node: (n, 8) [t, x, y, z, qx, qy, qz, qw]}, and the rest."""
    node = shutil.which("node") or shutil.which("nodejs")
    assert node, "node is missing: run scripts/setup.sh test"
    args = [node, str(SAMPLE), str(path), "--nodes", ",".join(nodes), "--times", ",".join(map(repr, times))]
    if shots:
        args += ["--shots", ",".join(map(repr, shots)), "--png-dir", str(png_dir), "--width", "960"]
    p = subprocess.run(args, capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    result = json.loads(p.stdout)
    result["poses"] = {k: np.array(v) for k, v in result["poses"].items()}
    return result


def rotation(w, x, y, z):
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def angle(a, b):
    """The angle between two rotation matrices, rad."""
    return float(np.arccos(np.clip((np.trace(a.T @ b) - 1) / 2, -1, 1)))


def worst_errors(run, poses):
    """Largest rotation (rad) and centre-of-mass (m) error of three.js's poses against tumble's run."""
    worst_angle = worst_dist = 0.0
    for k, row in enumerate(poses):
        assert row[0] == pytest.approx(run.t[k])
        want = Y_UP @ rotation(*run.q[k])
        qx, qy, qz, qw = row[4:]
        worst_angle = max(worst_angle, angle(rotation(qw, qx, qy, qz), want))
        worst_dist = max(worst_dist, float(np.linalg.norm(row[1:4] - Y_UP @ run.c[k])))
    return worst_angle, worst_dist


def out_dir(tmp_path):
    d = pathlib.Path(os.environ.get("TUMBLE_PY_OUT", tmp_path)) / "gltf_viewer"
    d.mkdir(parents=True, exist_ok=True)
    return d


def test_three_js_plays_the_fast_spin_as_simulated(tmp_path):
    """The 8 rad/s T-handle at 1 key per second (and the keys the export adds): three.js's pose at every
    mid-key time of the 1 s grid and every 0.05 s between is within the export's tolerance of the simulation."""
    scene = tumble.Scene.load(SCENES / "dzhanibekov.toml")
    path = out_dir(tmp_path) / "dzhanibekov_fps1.glb"
    tumble.export_gltf(scene, path, fps=1)
    times = [round(0.05 * k, 6) for k in range(1, 320)]  # every 0.05 s: each mid-key time k + 0.5 s among them
    shots = [0.5, 2.5, 5.5]
    result = play(path, ["t_handle", "t_handle_principal_axes"], times, shots, out_dir(tmp_path))
    # The documented names come through three.js unchanged (it strips . : / [ ] from names).
    assert {"t_handle", "t_handle_shape", "t_handle_principal_axes", "camera", "camera_light"} <= set(result["names"])
    assert result["cameras"] == 1 and result["lights"] == 1
    run = tumble.simulate(scene, times=times)[0]
    worst_angle, worst_dist = worst_errors(run, result["poses"]["t_handle"])
    print(f"three.js r{result['three']} vs tumble at {len(times)} times: {worst_angle:.2e} rad, {worst_dist:.2e} m")
    assert worst_angle <= 1e-3 + SLACK
    assert worst_dist <= 1e-6
    for t in shots:
        assert pathlib.Path(result["shots"][str(t)]).stat().st_size > 1000


def test_three_js_sees_a_thrown_body_rise_along_y(tmp_path):
    scene = tumble.Scene.load(SCENES / "thrown_box.toml")  # thrown up (+z in tumble) at 8.8 m/s under 9.81 m/s²
    path = out_dir(tmp_path) / "thrown_box_fps1.glb"
    tumble.export_gltf(scene, path, fps=1)
    times = [0.0, 0.45, 0.897, 1.35]
    result = play(path, ["box"], times, [0.45], out_dir(tmp_path))
    pose = result["poses"]["box"]
    assert pose[2, 2] == pytest.approx(8.8 ** 2 / (2 * 9.81), abs=2e-3)  # the top, v²/2g up +y
    assert pose[1, 2] > pose[0, 2] and abs(pose[:, 3]).max() < 1e-6
    run = tumble.simulate(scene, times=times)[0]
    worst_angle, worst_dist = worst_errors(run, pose)
    assert worst_angle <= 1e-3 + SLACK
    radius = float(np.linalg.norm(np.array([0.4, 0.25, 0.1]))) / 2
    assert worst_dist <= 1e-3 * radius * 1.01
