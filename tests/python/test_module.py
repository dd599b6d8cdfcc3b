"""The package imports from the build tree and carries the library's version."""
import re

import shadowlab


def test_version_is_the_projects():
    assert re.fullmatch(r"\d+\.\d+(\.\d+)?", shadowlab.__version__)
