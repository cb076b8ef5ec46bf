"""Reading and parsing: source lines, input limits, the parser and its fast paths, the syntax tree."""
