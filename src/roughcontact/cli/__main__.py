"""``python -m roughcontact.cli``: the ``roughcontact`` command line."""
import sys

from . import main

sys.exit(main())
