"""Python's arguments and settings go through the scene loader as the command line's options do: one override
path (scene::override_settings), so the checks are the same and so is every word after the option's name."""
import pytest

import tumble
from conftest import SCENES


def cli_error(cli, *args):
    p = cli(*args, check=False)
    assert p.returncode == 2, p.stderr
    return p.stderr.strip().splitlines()[-1]


def py_error(call):
    with pytest.raises(tumble.SceneError) as e:
        call()
    return str(e.value)


def same_after_option(py, cli_line, py_option, cli_option):
    assert py.startswith(py_option + ": error: "), py
    assert cli_line.startswith(cli_option + ": error: "), cli_line
    assert py[len(py_option):] == cli_line[len(cli_option):]


@pytest.mark.parametrize("kwargs,args,option", [
    ({"dt": -1.0}, ["--dt", "-1"], "dt"),
    ({"dt": 20.0}, ["--dt", "20"], "dt"),          # more than the 16 s duration
    ({"dt": 1e-9}, ["--dt", "1e-9"], "dt"),        # past the step cap
    ({"method": "rk5"}, ["--method", "rk5"], "method"),
])
def test_simulate_arguments_are_the_cli_options(tmp_path, cli, kwargs, args, option):
    scene = tumble.Scene.load(SCENES / "dzhanibekov.toml")
    line = cli_error(cli, "simulate", SCENES / "dzhanibekov.toml", "--csv", tmp_path / "x.csv", *args)
    same_after_option(py_error(lambda: tumble.simulate(scene, **kwargs)), line, f"tumble.simulate({option}=...)",
                      args[0])


@pytest.mark.parametrize("kwargs,args,option", [
    ({"width": 5}, ["--width", "5"], "width"),
    ({"height": 99999}, ["--height", "99999"], "height"),
    ({"aa": "smooth"}, ["--aa", "smooth"], "aa"),
])
def test_render_frame_arguments_are_the_cli_options(tmp_path, cli, kwargs, args, option):
    scene = tumble.Scene.load(SCENES / "thrown_box.toml")
    line = cli_error(cli, "render", SCENES / "thrown_box.toml", "--frames", "0:0", "--out", tmp_path, *args)
    same_after_option(py_error(lambda: tumble.render_frame(scene, frame=0, **kwargs)), line,
                      f"tumble.render_frame({option}=...)", args[0])


def test_export_fps_is_the_cli_option(tmp_path, cli):
    scene = tumble.Scene.load(SCENES / "thrown_box.toml")
    line = cli_error(cli, "export", SCENES / "thrown_box.toml", "--gltf", tmp_path / "x.glb", "--fps", "-2")
    same_after_option(py_error(lambda: tumble.export_gltf(scene, tmp_path / "x.glb", fps=-2)), line,
                      "tumble.export_gltf(fps=...)", "--fps")


def test_setting_a_value_is_checked_as_the_file_value(tmp_path):
    """scene.simulation.dt = -1 is refused with the words a scene file's `dt = -1` gets."""
    text = (SCENES / "dzhanibekov.toml").read_text().replace("dt = 1e-3", "dt = -1")
    file_error = py_error(lambda: tumble.Scene.from_toml(text, base_dir=SCENES, name="f.toml"))
    scene = tumble.Scene.load(SCENES / "dzhanibekov.toml")

    def set_dt():
        scene.simulation.dt = -1

    edit_error = py_error(set_dt)
    assert edit_error.startswith("scene.simulation.dt: error: simulation.dt: ")
    assert edit_error.split(": error: ", 1)[1] == file_error.split(": error: ", 1)[1]
    assert scene.simulation.dt == 1e-3  # a refused value leaves the scene as it was


def test_settings_cross_checks_hold():
    scene = tumble.Scene.load(SCENES / "dzhanibekov.toml")
    with pytest.raises(tumble.SceneError, match=r"simulation\.tolerance: expected method = \"auto\" with a tolerance"):
        scene.simulation.tolerance = 1e-3
    scene.simulation.method = "auto"
    scene.simulation.tolerance = 1e-3
    assert (scene.simulation.method, scene.simulation.tolerance) == ("auto", 1e-3)
    with pytest.raises(tumble.SceneError, match=r"output\.width: expected an integer in \[16, 16384\], found 8"):
        scene.output.width = 8
    scene.output.video = "gif"
    assert scene.output.video == "gif"
