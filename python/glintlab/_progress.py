"""Progress bars of long calls (render, compare, sweep): tqdm's text bar on
stderr, which a terminal and a Jupyter notebook both show. A bar appears
only once its call has run for a second, so quick calls print nothing.

Every long call takes `progress`: None follows the module setting
(`glintlab.set_progress`, or the environment variable GLINTLAB_PROGRESS=0
to silence every bar), True shows a bar, False shows none, and a callable
is called with the fraction done in [0, 1] instead of a bar."""

import os
import sys

_DELAY_S = 1.0
_enabled = os.environ.get("GLINTLAB_PROGRESS", "1").strip().lower() not in ("0", "false", "no",
                                                                             "off")


def set_progress(enabled):
    """Shows (True) or silences (False) the progress bars of every later
    call that does not pass its own `progress`. Returns the previous
    setting. The environment variable GLINTLAB_PROGRESS=0 sets False at
    import."""
    global _enabled
    previous = _enabled
    _enabled = bool(enabled)
    return previous


def progress_enabled():
    """Whether calls without their own `progress` show a bar."""
    return _enabled


class _Bar:
    """A context manager: `update(fraction)` moves a 0-100 % bar; a user
    callable gets the fraction itself."""

    def __init__(self, progress, description):
        if progress is not None and not isinstance(progress, bool) and not callable(progress):
            raise TypeError(f"progress: expected None, True, False or a callable(fraction), got "
                            f"{type(progress).__name__}")
        self._callback = progress if callable(progress) else None
        self._bar = None
        show = _enabled if progress is None else progress is True
        if show:
            from tqdm.std import tqdm
            self._bar = tqdm(total=100, desc=description, unit="%", delay=_DELAY_S, leave=False,
                             file=sys.stderr, bar_format="{desc}: {percentage:3.0f}%|{bar}| "
                             "[{elapsed}<{remaining}]")
        self._shown = 0

    def update(self, fraction):
        fraction = min(max(float(fraction), 0.0), 1.0)
        if self._callback is not None:
            self._callback(fraction)
        elif self._bar is not None:
            steps = int(round(100 * fraction))
            if steps > self._shown:
                self._bar.update(steps - self._shown)
                self._shown = steps

    @property
    def hook(self):
        """The callable to hand to the library, or None (no bar, no callback)."""
        return self.update if (self._bar is not None or self._callback is not None) else None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        if self._bar is not None:
            self._bar.close()
        return False
