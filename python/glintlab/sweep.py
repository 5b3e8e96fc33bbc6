"""`python3 -m glintlab.sweep SWEEP.json [--scheduler tcp://host:8786] [-o DIR]`.

The sweep itself lives in glintlab._sweep (glintlab.sweep is that function;
tasks pickle as glintlab._sweep.* so workers import them from the package)."""

import sys
import types

from glintlab._sweep import main, sweep


class _CallableModule(types.ModuleType):
    """`import glintlab.sweep` rebinds the package attribute `sweep` to this
    module; calling it still runs the sweep function."""

    def __call__(self, *args, **kwargs):
        return sweep(*args, **kwargs)


if __name__ == "__main__":
    main()
else:
    sys.modules[__name__].__class__ = _CallableModule
