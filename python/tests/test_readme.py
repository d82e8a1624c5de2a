"""The README's "From Python" block runs as written (from the repository root, as the README's commands do)."""

from __future__ import annotations

import numpy as np

from conftest import REPO


def test_readme_python_block_runs(monkeypatch) -> None:
    text = (REPO / "README.md").read_text()
    section = text[text.index("## From Python") :]
    block = section.split("```python\n", 1)[1].split("```", 1)[0]
    monkeypatch.chdir(REPO)
    names: dict = {}
    exec(compile(block, "README.md (From Python)", "exec"), names)
    assert len(names["q"]) == 50 and all(isinstance(v, float) for v in names["q"])
    assert names["run"].pressure.dtype == np.float64
    assert names["loop"].history("lemke")["tangential_shift"].shape == (11,)
