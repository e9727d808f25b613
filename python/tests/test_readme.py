"""The Python examples of README.md and docs/*.md run as written (from the repository root)."""
import re

import pytest

from conftest import SOURCE_DIR

DOCS = [SOURCE_DIR / "README.md", *sorted((SOURCE_DIR / "docs").glob("*.md"))]
BLOCKS = [(doc.relative_to(SOURCE_DIR), code) for doc in DOCS
          for code in re.findall(r"```python\n(.*?)```", doc.read_text(), re.S)]


def test_docs_have_examples():
    names = {str(doc) for doc, _ in BLOCKS}
    assert "README.md" in names and "docs/python.md" in names and "docs/gltf.md" in names, names


@pytest.mark.parametrize("block", range(len(BLOCKS)), ids=lambda i: f"{BLOCKS[i][0]}-{i}")
def test_doc_example_runs(tmp_path, monkeypatch, block):
    monkeypatch.chdir(SOURCE_DIR)
    doc, code = BLOCKS[block]
    code = code.replace('"wing_nut.glb"', repr(str(tmp_path / "wing_nut.glb")))
    exec(compile(code, f"{doc} python block {block}", "exec"), {})
