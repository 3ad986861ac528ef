# Image I/O tests.
