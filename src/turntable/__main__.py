"""``python -m turntable``: the ``turntable`` command (`turntable.cli`)."""

import sys

from turntable.cli import main

if __name__ == "__main__":
    sys.exit(main())
