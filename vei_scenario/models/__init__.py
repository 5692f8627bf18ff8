"""Pure numerical models (no I/O): shared by compile, the interpreter, the batch engine and FMU tests."""
