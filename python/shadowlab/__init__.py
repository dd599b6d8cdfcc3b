"""shadowlab from Python: load and prepare scenes, render a frame with a shadow technique,
read its buffers as numpy arrays, score it against the exact reference, and run sweeps and
fly-throughs (docs/python.md)."""

from ._shadowlab import __version__  # noqa: F401  (the library's version)
from .sweeps import (FlythroughFrame, FlythroughResults, FlythroughSeries, SweepResults, SweepRow,  # noqa: F401
                     flythrough, merge_sweeps, sweep)
