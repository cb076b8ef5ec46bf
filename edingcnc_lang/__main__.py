"""``python -m edingcnc_lang`` is the ``ecnc`` command."""
from edingcnc_lang.cli import entry

if __name__ == "__main__":  # not when a worker process (lint -j) imports the main module again
    entry()
