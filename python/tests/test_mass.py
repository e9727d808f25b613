"""Mass properties: point masses against numpy's sum, a mesh against `tumble info`."""
import json

import numpy as np
import pytest

import tumble
from conftest import SCENES


def test_point_masses_match_the_definition():
    rng = np.random.default_rng(7)
    points = rng.normal(size=(200, 3)) * [0.3, 0.2, 0.1]
    masses = rng.uniform(0.5, 2.0, size=200)
    p = tumble.mass_properties(points, masses)
    com = (masses[:, None] * points).sum(0) / masses.sum()
    r = points - com
    inertia = sum(m * (x @ x * np.eye(3) - np.outer(x, x)) for m, x in zip(masses, r))
    assert p.mass == pytest.approx(masses.sum(), rel=1e-14)
    np.testing.assert_allclose(p.com, com, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(p.inertia, inertia, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(p.principal_moments, np.linalg.eigvalsh(inertia), rtol=1e-10)
    axes = p.principal_axes
    np.testing.assert_allclose(axes.T @ inertia @ axes, np.diag(p.principal_moments), atol=1e-12)
    assert np.linalg.det(axes) == pytest.approx(1.0)


def test_degenerate_points_raise():
    with pytest.raises(tumble.SceneError, match="points"):
        tumble.mass_properties(np.zeros((1, 3)), np.ones(1))


def test_mesh_equals_tumble_info(cli):
    """The shipped wing nut read as wing_nut.toml reads it: the same numbers as `tumble info --json`."""
    info = json.loads(cli("info", SCENES / "wing_nut.toml", "--json").stdout)
    p = tumble.mesh_properties(SCENES / "meshes/wing_nut.stl", units="mm", density=7850.0, inertia_tolerance=1e-4)
    body, mesh = info["bodies"][0], info["bodies"][0]["meshes"][0]
    assert p.mass == body["mass"]
    assert p.particles == mesh["particles"]
    assert p.has_exact and p.mesh["watertight"]
    np.testing.assert_array_equal(p.exact_inertia, np.array(mesh["exact_inertia"]))
    np.testing.assert_allclose(p.inertia, np.array(body["inertia"]), rtol=1e-12, atol=1e-18)
    assert p.inertia_error == mesh["relative_error"] and p.inertia_error < 1e-4
