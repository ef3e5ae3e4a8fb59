"""The code of docs/python.md's section "The analyses" runs as written (numbers checked in
test_native.py).

Run by ctest with NEWTOP_PYTHON_MODULE (build/python) set (tests/python/CMakeLists.txt)."""

import os
import re
import sys

sys.path.insert(0, os.environ["NEWTOP_PYTHON_MODULE"])

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def section_code(title):
    text = open(os.path.join(ROOT, "docs", "python.md"), encoding="utf-8").read()
    body = text.split("## " + title + "\n", 1)[1].split("\n## ", 1)[0]
    return re.findall(r"```python\n(.*?)```", body, re.S)


def test_the_analyses_section_runs(monkeypatch):
    monkeypatch.chdir(ROOT)  # the snippets name examples/... as from the repository's root
    blocks = section_code("The analyses")
    assert blocks
    for code in blocks:
        namespace = {}
        exec(compile(code, "docs/python.md", "exec"), namespace)
        assert namespace["sec"].t.shape == (200,)
        assert namespace["an"].case == "lagrange"
