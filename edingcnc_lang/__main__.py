"""``python -m edingcnc_lang`` is the ``ecnc`` command."""
from .cli import entry

entry()
