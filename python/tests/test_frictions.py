"""Python as its users expect: messages about the call they made, warnings as warnings, any time in range,
numpy values, readable reprs, copies, a resume that keeps the edits, an installed module that renders."""
import copy
import os
import pathlib
import re
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import tumble
from conftest import SCENES, SOURCE_DIR

WING_NUT = SCENES / "meshes/wing_nut.stl"


def error_of(call):
    with pytest.raises(tumble.SceneError) as e:
        call()
    return str(e.value)


def test_mesh_properties_says_both_were_given():
    text = error_of(lambda: tumble.mesh_properties(WING_NUT, units="mm", mass=1, density=1))
    assert text == "tumble.mesh_properties(density=...): error: give mass or density, not both"


@pytest.mark.parametrize("kwargs,argument", [
    ({"units": "furlong", "mass": 1.0}, "units"),
    ({"mass": -1.0}, "mass"),
    ({"units": "mm", "mass": 1.0, "resolution": 1}, "resolution"),
    ({"units": "mm", "mass": 1.0, "fill": "solid"}, "fill"),
])
def test_mesh_properties_errors_name_the_argument(kwargs, argument):
    text = error_of(lambda: tumble.mesh_properties(WING_NUT, **kwargs))
    assert text.startswith(f"tumble.mesh_properties({argument}=...): error: "), text
    assert "bodies[0]" not in text and "scene" not in text and ":9:" not in text


def test_mesh_properties_missing_file_names_the_folder(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    text = error_of(lambda: tumble.mesh_properties("nowhere.stl", mass=1.0))
    assert text == f"tumble.mesh_properties(path=...): error: no such file: nowhere.stl (relative to the current folder, {tmp_path})"


@pytest.mark.parametrize("points,masses,argument", [
    ([[0, 0, 0]], [1.0], "points"),
    ([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [1.0, -1.0, 1.0], "masses"),
    (np.zeros((0, 3)), np.zeros(0), "points"),
    ([[0, 0, 0], [1, 0, 0]], [1.0], "masses"),
])
def test_mass_properties_errors_name_the_argument(points, masses, argument):
    text = error_of(lambda: tumble.mass_properties(points, masses))
    assert text.startswith(f"tumble.mass_properties({argument}=...): error: "), text
    assert "body '" not in text


def test_a_coarse_dt_warns_as_the_cli_does(cli, tmp_path):
    p = cli("simulate", SCENES / "dzhanibekov.toml", "--csv", tmp_path / "x.csv", "--method", "euler", "--dt", "0.5")
    # One warning per body (the demo's three T-handles), word for word the CLI's.
    prefix = "tumble: warning: "
    cli_warnings = [l[len(prefix):] for l in p.stderr.splitlines() if l.startswith(prefix)]
    assert cli_warnings
    scene = tumble.Scene.load(SCENES / "dzhanibekov.toml")
    with pytest.warns(tumble.TumbleWarning) as record:
        tumble.simulate(scene, method="euler", dt=0.5)
    assert [str(w.message) for w in record] == cli_warnings
    with _no_warning():
        tumble.simulate(scene, method="euler", dt=1e-3)


class _no_warning:
    def __enter__(self):
        import warnings
        self.catch = warnings.catch_warnings(record=True)
        self.record = self.catch.__enter__()
        warnings.simplefilter("always")

    def __exit__(self, *exc):
        self.catch.__exit__(*exc)
        assert not [w for w in self.record if issubclass(w.category, tumble.TumbleWarning)]


def test_render_frame_takes_any_time_in_range():
    scene = tumble.Scene.load(SCENES / "thrown_box.toml")  # 30 fps: frames at k/30 s
    at = lambda **kw: tumble.render_frame(scene, width=64, height=48, **kw)
    np.testing.assert_array_equal(at(t=0.01), at(frame=0))        # nearest: 0 s
    np.testing.assert_array_equal(at(t=0.02), at(frame=1))        # nearest: 1/30 s
    np.testing.assert_array_equal(at(t=scene.simulation.duration), at(frame=54))


def test_render_frame_out_of_range_says_so(cli):
    scene = tumble.Scene.load(SCENES / "dzhanibekov.toml")
    assert error_of(lambda: tumble.render_frame(scene, t=16.5)) == \
        "tumble.render_frame(t=16.5): error: expected a time in [0, 16] s, the scene's duration"
    # The scene's clock (title card, holds, slow motion), as `tumble info` counts it.
    count = int(re.search(r"^frames (\d+) at 30 fps", cli("info", SCENES / "dzhanibekov.toml").stdout, re.M).group(1))
    assert error_of(lambda: tumble.render_frame(scene, frame=-1)) == \
        f"tumble.render_frame(frame=-1): error: expected a frame index in 0..{count - 1} ({count} frames at 30 fps)"


def test_values_are_numpy_and_read_well():
    scene = tumble.Scene.load(SCENES / "dzhanibekov.toml")
    body = scene.bodies[0]
    assert isinstance(body.orientation, np.ndarray) and body.orientation.shape == (4,)
    assert isinstance(body.omega_body, np.ndarray)
    body.orientation = np.array([0.0, 0.0, 0.0, 2.0])
    np.testing.assert_array_equal(body.orientation, [0, 0, 0, 1])
    assert repr(scene.simulation) == ("SimulationConfig(method='splitting', dt=0.001, duration=16.0, fps=30.0, "
                                      "rtol=1e-09, atol=1e-12, tolerance=None)")
    assert repr(scene.output) == "OutputConfig(width=1280, height=720, fps=30.0, aa='fxaa', msaa=4, video='mp4')"


def test_deepcopy_is_independent():
    scene = tumble.Scene.load(SCENES / "dzhanibekov.toml")
    other = copy.deepcopy(scene)
    other.bodies[0].omega_body = (0, 1, 0)
    other.simulation.duration = 2.0
    assert scene.bodies[0].omega_body[1] == pytest.approx(8.0) and scene.simulation.duration == 16.0
    assert copy.copy(scene).simulation.duration == 16.0


def test_interrupted_render_resumes_with_the_python_edits(tmp_path, capfd, cli):
    scene = tumble.Scene.load(SCENES / "dzhanibekov.toml")
    scene.bodies[0].omega_body = (0.1, 6.0, 0.1)  # an edit the file does not have
    out = tmp_path / "render"

    def interrupt_after_the_first_frame():  # a signal once a frame is on disk; 480 more are left to render
        deadline = time.monotonic() + 120
        while not (out / "frame_000000.png").exists() and time.monotonic() < deadline:
            time.sleep(0.001)
        os.kill(os.getpid(), signal.SIGINT)

    threading.Thread(target=interrupt_after_the_first_frame, daemon=True).start()
    with pytest.raises(KeyboardInterrupt):
        tumble.render(scene, out, width=32, height=18, video="none")
    err = capfd.readouterr().err
    assert f"continue with: tumble.render(scene, '{out}', resume=True) with this same scene object" in err, err
    assert "tumble render" not in err
    summary = tumble.render(scene, out, width=32, height=18, video="none", resume=True)
    assert (out / "frame_000480.png").exists(), summary
    # The resumed folder's frames are the edited scene's, as one uninterrupted render makes them.
    whole = tmp_path / "whole"
    tumble.render(scene, whole, frames="470:480", width=32, height=18, video="none")
    for k in range(470, 481):
        assert (out / f"frame_{k:06d}.png").read_bytes() == (whole / f"frame_{k:06d}.png").read_bytes()
    # The command line's --resume of the unedited file does not continue the edited render: it replaces it.
    p = cli("render", SCENES / "dzhanibekov.toml", "-o", out, "--width", "32", "--height", "18", "--video", "none",
            "--resume", check=False)
    assert "replacing the earlier render" in p.stderr and "(scene or settings changed)" in p.stderr, p.stderr


def test_installed_module_renders_from_any_folder(tmp_path):
    build = pathlib.Path(os.environ.get("TUMBLE_PY_OUT", SOURCE_DIR / "build/release/python")).parent
    prefix = tmp_path / "prefix"
    p = subprocess.run(["cmake", "--install", str(build), "--prefix", str(prefix)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    site = next(prefix.glob("lib/python3*/dist-packages"))
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    code = ("import tumble, sys; r = tumble.resources(); print(r['shaders']); "
            f"s = tumble.Scene.load({str(SCENES / 'thrown_box.toml')!r}); "
            "print(tumble.render_frame(s, frame=3, width=64, height=48).shape)")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(site)
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=elsewhere, env=env)
    assert p.returncode == 0, p.stderr
    shaders, shape = p.stdout.split("\n")[:2]
    assert pathlib.Path(shaders).is_relative_to(site / "tumble"), shaders
    assert shape == "(48, 64, 3)"


def test_show_gives_notebook_display_objects():
    from IPython.display import Image, Video
    scene = tumble.Scene.load(SCENES / "thrown_box.toml")
    frame = tumble.show(scene, t=0.5, width=320)
    assert isinstance(frame, Image) and frame.data[:8] == b"\x89PNG\r\n\x1a\n"
    scene.simulation.duration = 0.3
    video = tumble.show(scene, width=320)
    assert isinstance(video, Video) and 'width="320"' in video._repr_html_()
    assert video.data[4:8] == b"ftyp"  # an MP4


def test_the_jupyter_the_docs_name_is_installed():
    p = subprocess.run(["jupyter", "notebook", "--version"], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
