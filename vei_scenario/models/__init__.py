"""Pure numerical models (no I/O): shared by compile, the interpreter, the sweep kernel and FMU tests."""
