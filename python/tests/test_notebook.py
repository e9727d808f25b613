"""The notebook runs headless (nbclient) without a cell error; the executed copy is kept in the build."""
import os
import pathlib

import nbformat
from nbclient import NotebookClient

from conftest import SOURCE_DIR

NOTEBOOK = SOURCE_DIR / "examples/notebooks/tumble_intro.ipynb"


def test_notebook_runs(monkeypatch):
    monkeypatch.delenv("MPLBACKEND", raising=False)  # the kernel's inline backend shows the figures
    nb = nbformat.read(NOTEBOOK, as_version=4)
    # Raises CellExecutionError (the test fails) on the first cell that raises.
    NotebookClient(nb, timeout=120, kernel_name="python3",
                   resources={"metadata": {"path": str(NOTEBOOK.parent)}}).execute()
    kinds = [o.get("data", {}).keys() for c in nb.cells if c.cell_type == "code" for o in c.outputs]
    assert any("image/png" in k for k in kinds), "no figure"
    assert any("text/html" in k for k in kinds), "no video"
    out = pathlib.Path(os.environ.get("TUMBLE_PY_OUT", SOURCE_DIR / "build")) / "tumble_intro.executed.ipynb"
    nbformat.write(nb, out)
