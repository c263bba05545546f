"""``python -m roughcontact.cli``: the ``roughcontact`` command line."""
import sys

from . import main

if __name__ == "__main__":   # not when imported (the API reference imports every module)
    sys.exit(main())
