#!/usr/bin/env python3
"""After scripts/demo.sh and scripts/test.sh in one clone: fails unless every
part the README promises was built and ran, so that nothing drops out of CI
without a word (a test that is not there cannot fail).

    check_parts.py ROOT CTEST_JUNIT_XML
"""
import glob
import json
import pathlib
import sys
import xml.etree.ElementTree as ET

# ctest tests that must have run and passed.
CTEST = ["python_tests", "python_module_built", "docs_links", "layers_point_down", "package_consumer"]
CTEST_PREFIX = ["GltfExport.", "BenchCli.", "DocsTool."]
# pytest cases (in python_tests) that must have run and passed.
PYTEST = {"test_notebook.test_notebook_runs_and_its_claims_hold": "the notebook",
          "test_gltf.test_every_shipped_scene_validates": "the Khronos glTF validator",
          "test_gltf_viewer.test_three_js_plays_the_fast_spin_as_simulated": "three.js playing the glTF export"}


def cases(xml_path):
    """{name: outcome} of a JUnit file: 'passed', or why not."""
    out = {}
    for tc in ET.parse(xml_path).getroot().iter("testcase"):
        name = tc.get("name")
        if tc.get("classname") and not tc.get("classname").startswith(name):
            name = f"{tc.get('classname').split('.')[-1]}.{name}"
        bad = [c.tag for c in tc if c.tag in ("failure", "error", "skipped")]
        status = tc.get("status", "run")
        out[name] = "passed" if not bad and status in ("run", "passed") else (",".join(bad) or status)
    return out


def main():
    root, ctest_xml = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    build = root / "build/release"
    problems = []
    manifest = root / "out/dzhanibekov/manifest.json"
    if not manifest.exists() or not json.loads(manifest.read_text()).get("complete"):
        problems.append(f"the demo: {manifest} missing or not complete")
    elif not (root / "out/dzhanibekov/dzhanibekov.mp4").exists():
        problems.append("the demo: no out/dzhanibekov/dzhanibekov.mp4")
    if not glob.glob(str(build / "python/tumble/_tumble*.so")):
        problems.append("the Python module: no build/release/python/tumble/_tumble*.so")
    ctest = cases(ctest_xml) if ctest_xml.exists() else {}
    if not ctest:
        problems.append(f"ctest: no results in {ctest_xml}")
    for name in CTEST:
        if ctest.get(name) != "passed":
            problems.append(f"ctest {name}: {ctest.get(name, 'not run')}")
    for prefix in CTEST_PREFIX:
        got = {n: s for n, s in ctest.items() if n.startswith(prefix)}
        if not got or any(s != "passed" for s in got.values()):
            problems.append(f"ctest {prefix}*: {got or 'not run'}")
    pytest_xml = build / "python/pytest.xml"
    py = cases(pytest_xml) if pytest_xml.exists() else {}
    for name, what in PYTEST.items():
        if py.get(name) != "passed":
            problems.append(f"{what} (pytest {name}): {py.get(name, 'not run')}")
    for p in problems:
        print("ci: MISSING:", p)
    if problems:
        return 1
    print(f"ci: every promised part built and passed ({len(ctest)} ctest tests, {len(py)} pytest cases)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
