"""``python -m edingcnc_lang`` is the ``ecnc`` command."""
import sys

from .cli import main

sys.exit(main())
