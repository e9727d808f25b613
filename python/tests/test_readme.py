"""The README's Python examples run as written (from the repository root)."""
import os
import re

import pytest

from conftest import SOURCE_DIR

BLOCKS = re.findall(r"```python\n(.*?)```", (SOURCE_DIR / "README.md").read_text(), re.S)


def test_readme_has_examples():
    assert len(BLOCKS) >= 2


@pytest.mark.parametrize("block", range(len(BLOCKS)))
def test_readme_example_runs(tmp_path, monkeypatch, block):
    monkeypatch.chdir(SOURCE_DIR)
    code = BLOCKS[block].replace('"wing_nut.glb"', repr(str(tmp_path / "wing_nut.glb")))
    exec(compile(code, f"README.md python block {block}", "exec"), {})
