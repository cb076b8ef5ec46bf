"""``python -m edingcnc_lang.lsp``: the language server, also without the ``ecnc`` command."""
import sys

from ..errors import MissingExtra
from . import main

try:
    sys.exit(main())
except MissingExtra as err:
    print(err.format(), file=sys.stderr)
    sys.exit(err.exit_code)
