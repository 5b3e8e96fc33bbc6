"""`python3 -m glintlab ARGS`: the glintlab command of this environment,
for notebooks and scripts whose PATH lacks the environment's bin/."""

from ._cli import main

main()
