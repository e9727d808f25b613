"""The notebook runs headless (nbclient) without a cell error, its claims hold in its own outputs, and its video
reads; the executed copy is kept in the build."""
import os
import pathlib
import re

import nbformat
from nbclient import NotebookClient

from conftest import SOURCE_DIR

NOTEBOOK = SOURCE_DIR / "examples/notebooks/tumble_intro.ipynb"


def run_notebook():
    nb = nbformat.read(NOTEBOOK, as_version=4)
    # Raises CellExecutionError (the test fails) on the first cell that raises.
    NotebookClient(nb, timeout=120, kernel_name="python3",
                   resources={"metadata": {"path": str(NOTEBOOK.parent)}}).execute()
    out = pathlib.Path(os.environ.get("TUMBLE_PY_OUT", SOURCE_DIR / "build")) / "tumble_intro.executed.ipynb"
    nbformat.write(nb, out)
    return nb


def text_of(cell):
    return "".join(o.get("text", "") for o in cell.outputs if o.get("output_type") == "stream")


def test_notebook_runs_and_its_claims_hold(monkeypatch):
    monkeypatch.delenv("MPLBACKEND", raising=False)  # the kernel's inline backend shows the figures
    nb = run_notebook()
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs]
    assert any("image/png" in o.get("data", {}) for o in outputs), "no figure"
    videos = [o["data"]["text/html"] for o in outputs if "<video" in o.get("data", {}).get("text/html", "")]
    assert videos, "no video"
    width = int(re.search(r'width="(\d+)"', videos[0]).group(1))
    assert width >= 640, f"video {width} px wide: its text does not read"
    prose = "\n".join(c.source for c in nb.cells if c.cell_type == "markdown")
    assert "energy-preserving" not in prose  # splitting's energy error is bounded, not zero
    # "rk4's energy error is the smaller one here, but it is a drift ... Over a long run the drift wins."
    numbers = {}
    for line in "".join(text_of(c) for c in nb.cells if c.cell_type == "code").splitlines():
        m = re.match(r"\s*(\d+) s (\w+)\s*: E\(end\) − E\(0\) = (\S+) J, largest \|E − E\(0\)\| = (\S+) J, "
                     r"largest \| \|L\| − \|L\(0\)\| \| = (\S+)", line)
        if m:
            numbers[(int(m[1]), m[2])] = tuple(float(x) for x in m.groups()[2:])
    assert len(numbers) == 4, numbers
    assert numbers[16, "rk4"][1] < numbers[16, "splitting"][1]                      # smaller here
    assert abs(numbers[1000, "rk4"][0]) > 10 * abs(numbers[16, "rk4"][0])           # a drift
    assert abs(numbers[1000, "rk4"][0]) > abs(numbers[1000, "splitting"][0])        # the drift wins
    assert numbers[1000, "splitting"][1] <= 1.01 * numbers[16, "splitting"][1]      # bounded
    assert numbers[1000, "splitting"][2] == 0.0                                     # |L| exactly
