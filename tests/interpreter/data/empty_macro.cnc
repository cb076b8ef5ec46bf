;@unit mm
; An empty macro file: tests that do not want the packaged macros use it.
