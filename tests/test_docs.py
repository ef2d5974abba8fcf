"""The documentation stays true: the API reference regenerates and every guide example runs."""

import re
import subprocess
import sys
from pathlib import Path

import pytest

DOCS = Path(__file__).resolve().parent.parent / "docs"
BLOCKS = re.findall(r"^```python\n(.*?)^```", (DOCS / "guide.md").read_text(encoding="utf-8"), flags=re.S | re.M)


def test_api_reference_regenerates(tmp_path):
    subprocess.run([sys.executable, str(DOCS / "build_api.py"), str(tmp_path / "api.md")], check=True,
                   capture_output=True)
    text = (tmp_path / "api.md").read_text(encoding="utf-8")
    assert BLOCKS and all(name in text for name in ("System", "simulate", "Holonomic", "RigidBody"))


@pytest.mark.slow
@pytest.mark.parametrize("code", BLOCKS, ids=[f"block{i}" for i in range(len(BLOCKS))])
def test_guide_example_runs(code, tmp_path):
    subprocess.run([sys.executable, "-c", code], check=True, cwd=tmp_path, timeout=300)
