"""``python -m msmesh ARGS...`` runs the msmesh program: ``msmesh ARGS...`` (msmesh._cli);
``python -m msmesh batch ...`` runs the batch runner (msmesh.batch) in this interpreter."""

import sys

from ._cli import main

if __name__ == "__main__":
    sys.exit(main())
