"""tumble.simulate against `tumble simulate --csv`: every number to the last digit."""
import csv
import os
import signal
import threading
import time

import numpy as np
import pytest

import tumble
from conftest import SCENES, run_cli

COLUMNS = [("c", 3), ("q", 4), ("v", 3), ("omega_world", 3), ("L", 3), ("energy", 0)]


def csv_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def assert_equal_to_csv(runs, rows):
    """Each CSV row equals the arrays' value printed as the CLI prints it (%.17g)."""
    names = {"c": ["cx", "cy", "cz"], "q": ["qw", "qx", "qy", "qz"], "v": ["vx", "vy", "vz"],
             "omega_world": ["wx", "wy", "wz"], "L": ["Lx", "Ly", "Lz"], "energy": ["energy"],
             "omega_body": ["wbx", "wby", "wbz"]}
    n = len(runs[0])
    assert len(rows) == n * len(runs)
    for k in range(n):
        for b, run in enumerate(runs):
            row = rows[k * len(runs) + b]
            assert row["body"] == run.body
            assert row["t"] == "%.17g" % run.t[k]
            for col, cols in names.items():
                values = np.atleast_1d(getattr(run, col)[k])
                got = ["%.17g" % x for x in values]
                assert got == [row[c] for c in cols], (k, run.body, col)


@pytest.mark.parametrize("scene,args,kwargs", [
    ("dzhanibekov.toml", [], {}),
    ("thrown_box.toml", ["--method", "rk4", "--dt", "0.002"], {"method": "rk4", "dt": 0.002}),
    ("methods_compare.toml", ["--method", "rk45"], {"method": "rk45"}),
    ("symmetric_top.toml", ["--method", "exact"], {"method": "exact"}),
])
def test_simulate_equals_cli_csv(tmp_path, cli, scene, args, kwargs):
    out = tmp_path / "run.csv"
    cli("simulate", SCENES / scene, "--csv", out, *args)
    runs = tumble.simulate(tumble.Scene.load(SCENES / scene), **kwargs)
    assert_equal_to_csv(runs, csv_rows(out))


def test_edited_scene_equals_edited_file(tmp_path, cli):
    """Setting omega_body in Python is the same as writing it in the file."""
    text = (SCENES / "dzhanibekov.toml").read_text()
    scene = tumble.Scene.from_toml(text, base_dir=SCENES)
    scene.bodies[0].omega_body = (0.1, 8, 0.1)
    scene.simulation.duration = 2.0
    edited = tmp_path / "edited.toml"
    lines = text.splitlines()
    first = next(i for i, ln in enumerate(lines) if ln.startswith("omega_body"))  # the first body's
    lines[first] = "omega_body = [0.1, 8.0, 0.1]"
    edited.write_text("\n".join(lines) + "\n")
    out = tmp_path / "run.csv"
    cli("simulate", edited, "--csv", out, "--duration", "2")
    assert_equal_to_csv(tumble.simulate(scene), csv_rows(out))


def test_arrays_are_read_only_views():
    run = tumble.simulate(tumble.Scene.load(SCENES / "dzhanibekov.toml"), times=[0, 0.5, 1.0])[0]
    assert run.c.shape == (3, 3) and run.q.shape == (3, 4) and run.energy.shape == (3,)
    assert not run.c.flags.owndata and not run.c.flags.writeable
    assert run.omega_body.base is not None  # a view of the C++ trajectory
    np.testing.assert_array_equal(run.t, [0, 0.5, 1.0])


def test_times_must_increase():
    scene = tumble.Scene.load(SCENES / "dzhanibekov.toml")
    with pytest.raises(tumble.SceneError, match=r"times\[1\]: expected times in increasing order"):
        tumble.simulate(scene, times=[1.0, 0.5])


def test_ctrl_c_stops_a_long_run():
    """SIGINT from another thread (which runs because the GIL is released) stops the run early."""
    scene = tumble.Scene.load(SCENES / "dzhanibekov.toml")
    scene.simulation.duration = 1e4  # 1e8 steps of 1e-4 s: minutes if Ctrl-C were ignored
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        tumble.simulate(scene, method="rk4", dt=1e-4)
    assert time.monotonic() - start < 5.0


def test_methods_table():
    names = [m["name"] for m in tumble.methods()]
    assert {"rk4", "rk45", "splitting", "exact"} <= set(names)
    assert all(m["order"] >= 0 for m in tumble.methods())


def test_methods_descriptions_are_the_cli_table():
    # One table: each row's description is the one `tumble methods` prints.
    rows = tumble.methods()
    assert all(m["description"].strip() for m in rows)
    assert len({m["description"] for m in rows}) == len(rows)
    out = run_cli("methods").stdout
    for m in rows:
        line = next(l for l in out.splitlines() if l.split() and l.split()[0] == m["name"])
        assert m["description"] in line, (m["name"], line)
