"""tumble.SceneError carries the command line's message (file:line:col)."""
import pytest

import tumble
from conftest import SCENES

BROKEN = """name = "broken"
[simulation]
dt = -0.001
duraton = 5.0

[[bodies]]
name = "b"
shape = { type = "box", size = [1, 2, 3], mass = 1.0 }
"""


def test_scene_error_text_equals_cli(tmp_path, cli):
    path = tmp_path / "broken.toml"
    path.write_text(BROKEN)
    p = cli("simulate", path, "--csv", tmp_path / "x.csv", check=False)
    assert p.returncode == 2
    with pytest.raises(tumble.SceneError) as e:
        tumble.Scene.load(path)
    assert str(e.value) == p.stderr.rstrip("\n")
    assert f"{path}:3:6: error" in str(e.value)
    first = e.value.diagnostics[0]
    assert (first["line"], first["column"], first["key"]) == (3, 6, "simulation.dt")
    assert isinstance(e.value, ValueError) and isinstance(e.value, tumble.Error)


def test_missing_file_error_equals_cli(tmp_path, cli):
    path = tmp_path / "nowhere.toml"
    p = cli("info", path, check=False)
    with pytest.raises(tumble.SceneError) as e:
        tumble.Scene.load(path)
    assert str(e.value) == p.stderr.rstrip("\n")


def test_from_toml_names_the_source():
    with pytest.raises(tumble.SceneError, match=r"^lecture:3:6: error: simulation\.dt"):
        tumble.Scene.from_toml(BROKEN, name="lecture")


def test_bad_edit_is_a_value_error():
    scene = tumble.Scene.load(SCENES / "dzhanibekov.toml")
    with pytest.raises(ValueError, match="omega_body: expected 3 numbers"):
        scene.bodies[0].omega_body = (1, 2)
    with pytest.raises(tumble.SceneError, match=r'^tumble\.simulate\(method=\.\.\.\): error: simulation\.method: expected .*found "rk5"'):
        tumble.simulate(scene, method="rk5")
