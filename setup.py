"""The optional compiled core (edingcnc_lang/_speedups.c, the macro line tokenizer
edingcnc_lang/_lexer.c, and the 3-axis sim's sweep edingcnc_lang/_sweep.c); everything else is in
pyproject.toml.

The extensions are ``optional``: without a C compiler the install goes on and the pure-Python core
runs (``ecnc --version`` says which).  It uses the stable ABI, so one wheel serves Python 3.10+.
"""
from glob import glob

from setuptools import Extension, setup

# Each extension is one translation unit whose parts (a part per job) it includes from csrc/: a change
# to a part rebuilds it.
PARTS = {name: ["edingcnc_lang/csrc/common.c", *sorted(glob(f"edingcnc_lang/csrc/{name}_*.c"))]
         for name in ("speedups", "lexer")}

setup(
    ext_modules=[Extension("edingcnc_lang._speedups", ["edingcnc_lang/_speedups.c"], depends=PARTS["speedups"],
                           optional=True,
                           py_limited_api=True, define_macros=[("Py_LIMITED_API", "0x030A0000")],
                           extra_compile_args=["-O2", "-ffp-contract=off"]),
                 Extension("edingcnc_lang._lexer", ["edingcnc_lang/_lexer.c"], depends=PARTS["lexer"], optional=True,
                           py_limited_api=True, define_macros=[("Py_LIMITED_API", "0x030A0000")],
                           extra_compile_args=["-O2", "-ffp-contract=off"]),
                 # the buffer protocol is in the stable ABI from 3.11: on 3.10 this one is not built
                 Extension("edingcnc_lang._sweep", ["edingcnc_lang/_sweep.c"], optional=True,
                           py_limited_api=True, define_macros=[("Py_LIMITED_API", "0x030B0000")],
                           extra_compile_args=["-O2", "-ffp-contract=off"])],
    options={"bdist_wheel": {"py_limited_api": "cp310"}},
)
