"""Kinematics plug-ins shipped with edingcnc-lang (installed as ``edingcnc_lang.kins``).

``rotatekins`` and ``deltakins`` are Python plug-ins registered under the entry-point group
``edingcnc_lang.kinematics``; ``c/`` holds the C header for compiled plug-ins and the C
version of rotatekins.
"""
