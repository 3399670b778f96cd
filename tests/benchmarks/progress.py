"""Progress bars for the benchmark scripts' long loops (scenes, settings, frames, ...).

The benchmarks run for minutes (random_scenes.py for half an hour) with little to show: a bar
on their long loops says how far a run is and what is left. It is written to stderr, so that
what a script measures and prints (stdout: its tables and figures) and writes (CSV, Markdown)
is unchanged. No bar without tqdm (Debian's python3-tqdm) or with LIGHTSHAFTS_NO_PROGRESS set
(non-empty); when stderr is not a terminal (a log) the bar is written every 5 s at most.

    import progress
    for scene in progress.steps(scenes, "scenes"):
        ...
"""

import os
import sys


def steps(iterable, description, total=None):
    """`iterable`, its items counted on a bar on stderr named `description` (`total`: the
    number of items, when len(iterable) is not it). Without tqdm, or with
    LIGHTSHAFTS_NO_PROGRESS set, `iterable` itself."""
    if os.environ.get("LIGHTSHAFTS_NO_PROGRESS"):
        return iterable
    try:
        from tqdm import tqdm
    except ImportError:
        return iterable
    return _counted(tqdm, iterable, description, total)


def _isatty(stream):
    try:
        return stream.isatty()
    except (AttributeError, ValueError):
        return False


class _AboveTheBars:
    """A terminal's stdout or stderr while a bar is drawn on it: whole lines are written with
    the bars cleared first and drawn again after (tqdm.write's way), not after a bar's text."""

    def __init__(self, tqdm, stream, bars):
        self.wrapped, self._tqdm, self._bars, self._partial = stream, tqdm, bars, ""

    def write(self, text):
        lines, newline, self._partial = (self._partial + text).rpartition("\n")
        if newline:
            with self._tqdm.external_write_mode(file=self._bars):
                self.wrapped.write(lines + newline)
                self.wrapped.flush()
        return len(text)

    def finish(self):
        self.wrapped.write(self._partial)
        self.wrapped.flush()

    def __getattr__(self, name):
        return getattr(self.wrapped, name)


def _counted(tqdm, iterable, description, total):
    bars = sys.stderr
    if isinstance(bars, _AboveTheBars):  # (a bar inside another's loop)
        bars = bars.wrapped
    terminal = _isatty(bars)
    bar = tqdm(iterable, desc=description, total=total, file=bars, leave=False,
               dynamic_ncols=True, mininterval=0.1 if terminal else 5)
    swapped = []
    if terminal:
        for name in ("stdout", "stderr"):
            stream = getattr(sys, name)
            if _isatty(stream) and not isinstance(stream, _AboveTheBars):
                swapped.append((name, stream, _AboveTheBars(tqdm, stream, bars)))
                setattr(sys, name, swapped[-1][2])
    try:
        yield from bar
    finally:
        bar.close()
        for name, stream, wrapper in reversed(swapped):
            setattr(sys, name, stream)
            wrapper.finish()
