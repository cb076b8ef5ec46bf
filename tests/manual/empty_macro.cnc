;@unit mm
; No macros: the manual cases run the built-in codes alone.
