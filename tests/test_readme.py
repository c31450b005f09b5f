"""The README's library example runs as written (in a temporary folder: it writes patch.obj)."""

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def test_readme_library_example_runs(tmp_path, monkeypatch):
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    section = text[text.index("## Using the library"):]
    code = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    monkeypatch.chdir(tmp_path)
    namespace: dict = {}
    exec(compile(code, "README.md", "exec"), namespace)
    assert (tmp_path / "patch.obj").stat().st_size > 0
    assert namespace["xyz"].shape == (5, 3)
    assert namespace["q"](namespace["rp"], arith="exact").shape == (2, 3)
