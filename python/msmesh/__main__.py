"""``python -m msmesh ARGS...`` runs the msmesh program: ``msmesh ARGS...`` (msmesh._cli)."""

import sys

from ._cli import main

if __name__ == "__main__":
    sys.exit(main())
