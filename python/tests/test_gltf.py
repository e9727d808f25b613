"""`tumble export --gltf` of every shipped scene, validated by the Khronos glTF-Validator: 0 errors.

The validator (npm gltf-validator) is installed by `scripts/setup.sh test`; without it this test FAILS.
The keyframes are read back with tinygltf in tests/gltf (gltf_tests)."""
import json
import os
import pathlib
import shutil
import subprocess

import pytest

import tumble
from conftest import SCENES, SOURCE_DIR

VALIDATE = SOURCE_DIR / "tools/validate_gltf.js"


def validate(files, report):
    node = shutil.which("node") or shutil.which("nodejs")
    assert node, "node is missing: run scripts/setup.sh test"
    p = subprocess.run([node, str(VALIDATE), "--json", str(report), *map(str, files)], capture_output=True, text=True)
    print(p.stdout, p.stderr)
    assert p.returncode == 0, p.stdout + p.stderr
    return json.loads(pathlib.Path(report).read_text())


def test_every_shipped_scene_validates(tmp_path, cli):
    out = pathlib.Path(os.environ.get("TUMBLE_PY_OUT", tmp_path)) / "gltf"
    out.mkdir(parents=True, exist_ok=True)
    files = []
    for scene in sorted(SCENES.glob("*.toml")):
        f = out / (scene.stem + ".glb")
        cli("export", scene, "--gltf", f)
        files.append(f)
    files.append(out / "dzhanibekov.gltf")  # the JSON form, buffer embedded
    cli("export", SCENES / "dzhanibekov.toml", "--gltf", files[-1], "--fps", "10")
    reports = validate(files, out / "validator-report.json")
    assert len(reports) == len(files)
    for r in reports:
        assert r["issues"]["numErrors"] == 0, r["uri"]
        assert r["info"]["animationCount"] == 1 and r["info"]["totalVertexCount"] > 0, r["uri"]


def test_python_export_equals_cli(tmp_path, cli):
    cli("export", SCENES / "thrown_box.toml", "--gltf", tmp_path / "cli.glb", "--fps", "12")
    tumble.export_gltf(tumble.Scene.load(SCENES / "thrown_box.toml"), tmp_path / "py.glb", fps=12)
    assert (tmp_path / "cli.glb").read_bytes() == (tmp_path / "py.glb").read_bytes()


def test_export_errors_name_the_option(tmp_path, cli):
    p = cli("export", SCENES / "thrown_box.toml", "--gltf", tmp_path / "x.glb", "--fps", "-1", check=False)
    assert p.returncode == 2 and "--fps" in p.stderr
    p = cli("export", SCENES / "thrown_box.toml", "--gltf", tmp_path / "x.obj", check=False)
    assert p.returncode == 2 and "expected a file name ending in .glb or .gltf" in p.stderr


def test_key_tolerance_option(tmp_path, cli):
    """--fps is a minimum: keys are added where the body turns fast, fewer with a looser --key-tolerance."""
    counts = {}
    for tol in ("0.001", "0.05"):
        p = cli("export", SCENES / "dzhanibekov.toml", "--gltf", tmp_path / f"k{tol}.glb", "--fps", "1",
                "--key-tolerance", tol)
        counts[tol] = int(p.stderr.split(" and ")[1].split()[0])  # "... 17 keyframes at 1 fps and N more ..."
    assert counts["0.001"] > counts["0.05"] > 0
    p = cli("export", SCENES / "dzhanibekov.toml", "--gltf", tmp_path / "x.glb", "--key-tolerance", "5", check=False)
    assert p.returncode == 2 and p.stderr.startswith("--key-tolerance: error: expected a number in [1e-05, 0.5] rad, found 5")
    with pytest.raises(tumble.SceneError, match=r"^tumble\.export_gltf\(key_tolerance=\.\.\.\): error: expected a number in \[1e-05, 0.5\] rad, found 5$"):
        tumble.export_gltf(tumble.Scene.load(SCENES / "dzhanibekov.toml"), tmp_path / "y.glb", key_tolerance=5)
