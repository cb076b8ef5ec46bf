"""The virtual machine: the interpreter (``interpreter.Interpreter``, assembled from one part per
module, each a mixin on ``state.MachineState``) and what it computes with: expressions
(``evaluator``), parameters, the tables of codes and their order of execution, canned cycles,
thread passes, spindle arithmetic, arc geometry, the job's own files.

It executes the syntax tree it is given and never imports the parser.  One Interpreter is one
machine; there is no global state.
"""
