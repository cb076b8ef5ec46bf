"""``python -m edingcnc_lang.lsp``: the language server, also without the ``ecnc`` command."""
import sys

from edingcnc_lang.errors import MissingExtra
from edingcnc_lang.lsp import main

try:
    sys.exit(main())
except MissingExtra as err:
    print(err.format(), file=sys.stderr)
    sys.exit(err.exit_code)
