"""docs/python.md's API reference is the one the built package's docstrings give
(scripts/python_api_docs.py): a docstring changed without the docs, or the reverse, fails."""
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]


def test_the_committed_reference_is_the_generated_one():
    check = subprocess.run([sys.executable, str(ROOT / "scripts" / "python_api_docs.py"), "--check",
                            str(ROOT / "docs" / "python.md")], capture_output=True, text=True)
    assert check.returncode == 0, check.stderr
