"""``python -m edingcnc_lang`` is the ``ecnc`` command."""
from .cli import main

main(prog_name="ecnc")
